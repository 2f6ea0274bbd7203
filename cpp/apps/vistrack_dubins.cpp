// vistrack_dubins: shortest Dubins lengths and words for configuration pairs read from CSV.
//
//   vistrack_dubins --rho R [--segments] [-o OUT.csv] IN.csv
//
// IN.csv: one pair per line, x0,y0,psi0,x1,y1,psi1 (rad); an optional header line (any line
// whose first field is not a number) and blank lines are skipped. An optional 7th column
// overrides rho for that row. OUT (stdout by default): length,word and, with --segments,
// seg1,seg2,seg3 (m). Rows share one rho are solved in one multi-threaded batch.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "vistrack/dubins.hpp"
#include "vistrack/error.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: vistrack_dubins --rho R [--segments] [-o OUT.csv] IN.csv\n"
         "  IN.csv rows: x0,y0,psi0,x1,y1,psi1[,rho]  (header and blank lines skipped)\n"
         "  writes: length,word[,seg1,seg2,seg3]\n";
}

bool parse_number(const std::string& text, double& value) {
  const char* begin = text.c_str();
  while (*begin == ' ' || *begin == '\t') ++begin;
  char* end = nullptr;
  value = std::strtod(begin, &end);
  if (end == begin) return false;
  while (*end == ' ' || *end == '\t' || *end == '\r') ++end;
  return *end == '\0';
}

struct Rows {
  std::vector<double> q0, q1, rho;
  std::vector<std::size_t> line;
};

Rows read_rows(const std::string& path, double default_rho) {
  std::ifstream in(path);
  if (!in) vistrack::detail::fail_field("input", path, "cannot open file for reading");
  Rows rows;
  std::string text;
  std::size_t line_number = 0;
  while (std::getline(in, text)) {
    ++line_number;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::vector<std::string> fields;
    std::stringstream stream(text);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    double first = 0.0;
    if (rows.line.empty() && !parse_number(fields[0], first)) continue;  // header
    const std::string where = path + ":" + std::to_string(line_number);
    if (fields.size() != 6 && fields.size() != 7)
      vistrack::detail::fail_field(where + " columns", fields.size(), "expected 6 (x0,y0,psi0,x1,y1,psi1) or 7 (+rho)");
    static const char* names[] = {"x0", "y0", "psi0", "x1", "y1", "psi1", "rho"};
    double values[7] = {0, 0, 0, 0, 0, 0, default_rho};
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (!parse_number(fields[k], values[k]))
        vistrack::detail::fail_field(where + " " + names[k], "'" + fields[k] + "'", "not a number");
      vistrack::require_finite(values[k], where + " " + names[k]);
    }
    vistrack::require_positive(values[6], where + " rho");
    rows.q0.insert(rows.q0.end(), values, values + 3);
    rows.q1.insert(rows.q1.end(), values + 3, values + 6);
    rows.rho.push_back(values[6]);
    rows.line.push_back(line_number);
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  double rho = -1.0;
  bool segments = false;
  std::string input, output;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "-h" || arg == "--help") {
      usage(std::cout);
      return 0;
    } else if (arg == "--rho" && k + 1 < argc) {
      if (!parse_number(argv[++k], rho)) rho = std::nan("");
    } else if (arg == "--segments") {
      segments = true;
    } else if ((arg == "-o" || arg == "--output") && k + 1 < argc) {
      output = argv[++k];
    } else if (!arg.empty() && arg[0] != '-' && input.empty()) {
      input = arg;
    } else {
      std::cerr << "vistrack_dubins: unknown argument '" << arg << "'\n";
      usage(std::cerr);
      return 2;
    }
  }
  if (input.empty()) {
    usage(std::cerr);
    return 2;
  }
  try {
    vistrack::require_positive(rho, "--rho");
    const Rows rows = read_rows(input, rho);
    const std::size_t n = rows.rho.size();
    std::vector<double> lengths(n);
    std::vector<std::uint8_t> words(n);
    bool one_rho = true;
    for (double r : rows.rho) one_rho &= r == rho;
    if (one_rho) {
      vistrack::dubins_shortest_lengths(rows.q0.data(), rows.q1.data(), n, rho, lengths.data(), words.data());
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        vistrack::DubinsWord w;
        lengths[i] = vistrack::dubins_shortest_length({rows.q0[3 * i], rows.q0[3 * i + 1], rows.q0[3 * i + 2]},
                                                      {rows.q1[3 * i], rows.q1[3 * i + 1], rows.q1[3 * i + 2]},
                                                      rows.rho[i], &w);
        words[i] = static_cast<std::uint8_t>(w);
      }
    }
    std::ofstream file;
    if (!output.empty()) {
      file.open(output);
      if (!file) vistrack::detail::fail_field("--output", output, "cannot open file for writing");
    }
    std::ostream& out = output.empty() ? std::cout : file;
    out.precision(17);
    out << (segments ? "length,word,seg1,seg2,seg3\n" : "length,word\n");
    for (std::size_t i = 0; i < n; ++i) {
      out << lengths[i] << ',' << vistrack::to_string(static_cast<vistrack::DubinsWord>(words[i]));
      if (segments) {
        const vistrack::DubinsPath p = vistrack::dubins_path(
            {rows.q0[3 * i], rows.q0[3 * i + 1], rows.q0[3 * i + 2]}, {rows.q1[3 * i], rows.q1[3 * i + 1], rows.q1[3 * i + 2]},
            rows.rho[i], static_cast<vistrack::DubinsWord>(words[i]));
        out << ',' << p.segment_lengths[0] << ',' << p.segment_lengths[1] << ',' << p.segment_lengths[2];
      }
      out << '\n';
    }
    if (!out) vistrack::detail::fail_field("--output", output.empty() ? "stdout" : output, "write failed");
  } catch (const vistrack::Error& e) {
    std::cerr << "vistrack_dubins: error: " << e.what() << '\n';
    return 2;
  }
  return 0;
}
