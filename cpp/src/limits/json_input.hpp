// JSON documents read from input files (GeoJSON maps, orbit plans): one parser with the nesting
// limit of vistrack/limits.hpp, and a bounded quote of a parsed value for messages.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace vistrack::detail {

// The JSON document in `text`. Error "<where>: not valid JSON (...)" for a syntax error or a
// number out of the doubles' range, and "<where>: nested deeper than kMaxDocumentDepth levels"
// refused while parsing, before the deep value exists (a 100,000-deep array crashed the
// recursive copy and dump that a message quoting it made).
nlohmann::json parse_json(const std::string& text, const std::string& where);

// A JSON value quoted in a message: compact JSON, at most 40 characters (then "..."), bytes
// outside printable ASCII as \xNN. Walks only as much of the value as it quotes, so a huge or
// deep value costs no more than a small one.
std::string json_preview(const nlohmann::json& value);

}  // namespace vistrack::detail
