// The JSON reader of limits/json_input.hpp.
#include "limits/json_input.hpp"

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"

namespace vistrack::detail {

namespace {

using nlohmann::json;

constexpr std::size_t kPreviewCharacters = 40;

// Appends `value` to `out` until `out` passes the preview's length; containers deeper than the
// document limit are not entered (a value built in code could be deeper than a parsed one).
void append_preview(const json& value, std::string& out, int depth) {
  if (out.size() > kPreviewCharacters) return;
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    const bool cut = text.size() > kPreviewCharacters;
    out += json(cut ? text.substr(0, kPreviewCharacters) : text).dump(-1, ' ', false, json::error_handler_t::replace);
    if (cut) out += "...";
    return;
  }
  if (!value.is_structured()) {
    out += value.dump();
    return;
  }
  const bool object = value.is_object();
  out += object ? '{' : '[';
  if (depth >= limits::kMaxDocumentDepth && !value.empty()) {
    out += "...";
  } else {
    bool first = true;
    for (auto it = value.begin(); it != value.end() && out.size() <= kPreviewCharacters; ++it) {
      if (!first) out += ',';
      first = false;
      if (object) {
        append_preview(json(it.key()), out, depth + 1);
        out += ':';
      }
      append_preview(*it, out, depth + 1);
    }
  }
  out += object ? '}' : ']';
}

}  // namespace

json parse_json(const std::string& text, const std::string& where) {
  // The parser reports each container's start at the depth of its parent (0 for the root).
  const json::parser_callback_t limit_depth = [&where](int depth, json::parse_event_t event, json&) {
    if ((event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) &&
        depth >= limits::kMaxDocumentDepth)
      throw Error(where + ": nested deeper than " + std::to_string(limits::kMaxDocumentDepth) +
                  " levels (the limit for an input document)");
    return true;
  };
  try {
    return json::parse(text, limit_depth);
  } catch (const json::exception& error) {  // syntax errors, and numbers out of range (1e999)
    // nlohmann's message quotes the token it stopped at, which may be the rest of the file.
    throw Error(where + ": not valid JSON (" + printable(error.what(), false, 200) + ")");
  }
}

std::string json_preview(const json& value) {
  std::string out;
  append_preview(value, out, 0);
  return printable(out, false);
}

}  // namespace vistrack::detail
