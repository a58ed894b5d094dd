#include "calculix_deck.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "coordinate_entries.hpp"
#include "stream_text.hpp"

namespace rsi {
namespace {

std::string upper(std::string_view s) {
  std::string u(s);
  for (char& c : u)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}

std::string trim(std::string_view s) {
  size_t a = 0;
  size_t b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a])))
    ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1])))
    --b;
  return std::string(s.substr(a, b - a));
}

std::vector<std::string> split_commas(std::string_view line) {
  std::vector<std::string> fields;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos
                                                                          : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

/// Value of PARAM=value on a keyword line (upper-cased), empty if absent.
std::string parameter(const std::vector<std::string>& fields, const std::string& name) {
  for (size_t i = 1; i < fields.size(); ++i) {
    const size_t eq = fields[i].find('=');
    if (eq != std::string::npos && upper(trim(fields[i].substr(0, eq))) == name)
      return trim(fields[i].substr(eq + 1));
  }
  return {};
}

/// A deck line with where it came from, for messages.
struct Where {
  std::string file;
  int line = 0;
  std::string text() const { return file + ":" + std::to_string(line); }
};

struct Line {
  std::string text;
  Where where;
};

/// The model part of `path` as lines, includes inlined; stops at *STEP.
bool collect_lines(const std::filesystem::path& path, std::vector<Line>& out, int depth) {
  if (depth > 16)
    throw ImportError(path.string() + ": *INCLUDE nested more than 16 deep (a cycle?)");
  const std::string text = read_whole_file(path.string());
  size_t offset = 0;
  std::string_view raw;
  int number = 0;
  while (next_line(text, offset, raw)) {
    ++number;
    const std::string line = trim(raw);
    const Where where{path.string(), number};
    if (line.rfind("*", 0) == 0 && line.rfind("**", 0) != 0) {
      const std::vector<std::string> fields = split_commas(line.substr(1));
      const std::string keyword = upper(fields[0]);
      if (keyword == "STEP") return true;
      if (keyword == "INCLUDE") {
        const std::string input = parameter(fields, "INPUT");
        if (input.empty())
          throw ImportError(where.text() + ": *INCLUDE without INPUT=file");
        std::filesystem::path included(input);
        if (included.is_relative()) included = path.parent_path() / included;
        if (!std::filesystem::exists(included))
          throw ImportError(where.text() + ": included file '" + included.string() +
                            "' does not exist");
        if (collect_lines(included, out, depth + 1)) return true;
        continue;
      }
    }
    out.push_back({line, where});
  }
  return false;
}

int parse_int(const std::string& field, const Where& where, const std::string& what) {
  int value = 0;
  const auto [p, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || p != field.data() + field.size())
    throw ImportError(where.text() + ": " + what + " must be an integer, got '" + field + "'");
  return value;
}

double parse_double(const std::string& field, const Where& where, const std::string& what) {
  double value = 0.0;
  const auto [p, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || p != field.data() + field.size() || !std::isfinite(value))
    throw ImportError(where.text() + ": " + what + " must be a finite number, got '" + field +
                      "'");
  return value;
}

} // namespace

CalculixDeck read_calculix_deck(const std::string& path) {
  CalculixDeck deck;
  deck.path = path;
  std::vector<Line> lines;
  collect_lines(std::filesystem::path(path), lines, 0);
  std::ostringstream model;
  enum class Block { other, node, nset, nset_generate } block = Block::other;
  std::vector<int>* nset = nullptr;
  for (const Line& line : lines) {
    model << line.text << "\n";
    if (line.text.empty() || line.text.rfind("**", 0) == 0) continue;
    if (line.text[0] == '*') {
      const std::vector<std::string> fields = split_commas(line.text.substr(1));
      const std::string keyword = upper(fields[0]);
      block = Block::other;
      if (keyword == "NODE") {
        block = Block::node;
        const std::string name = upper(parameter(fields, "NSET"));
        nset = name.empty() ? nullptr : &deck.nsets[name];
      } else if (keyword == "NSET") {
        const std::string name = upper(parameter(fields, "NSET"));
        if (name.empty()) throw ImportError(line.where.text() + ": *NSET without NSET=name");
        nset = &deck.nsets[name];
        const bool generate = std::any_of(fields.begin() + 1, fields.end(), [](const std::string& f) {
          return upper(f) == "GENERATE";
        });
        block = generate ? Block::nset_generate : Block::nset;
      }
      continue;
    }
    const std::vector<std::string> fields = split_commas(line.text);
    if (block == Block::node) {
      if (fields.size() < 2 || fields.size() > 4)
        throw ImportError(line.where.text() + ": a *NODE line is 'id, x[, y[, z]]'");
      ComponentNode node;
      node.id = parse_int(fields[0], line.where, "the node id");
      for (size_t k = 1; k < fields.size(); ++k)
        node.x(static_cast<int>(k - 1)) =
            fields[k].empty() ? 0.0 : parse_double(fields[k], line.where, "a coordinate");
      deck.nodes.push_back(node);
      if (nset) nset->push_back(node.id);
    } else if (block == Block::nset) {
      for (const std::string& f : fields)
        if (!f.empty()) {
          if (!std::isdigit(static_cast<unsigned char>(f[0])))
            throw ImportError(line.where.text() +
                              ": node sets given by name inside *NSET are not supported, got '" +
                              f + "'");
          nset->push_back(parse_int(f, line.where, "a node id"));
        }
    } else if (block == Block::nset_generate) {
      if (fields.size() < 2 || fields.size() > 3)
        throw ImportError(line.where.text() + ": a GENERATE line is 'first, last[, step]'");
      const int first = parse_int(fields[0], line.where, "first");
      const int last = parse_int(fields[1], line.where, "last");
      const int step = fields.size() == 3 && !fields[2].empty()
                           ? parse_int(fields[2], line.where, "step")
                           : 1;
      if (step < 1 || last < first)
        throw ImportError(line.where.text() + ": GENERATE needs first <= last and step >= 1");
      for (int id = first; id <= last; id += step)
        nset->push_back(id);
    }
  }
  deck.model_text = stream_text(model);
  std::sort(deck.nodes.begin(), deck.nodes.end(),
            [](const ComponentNode& a, const ComponentNode& b) { return a.id < b.id; });
  for (size_t k = 1; k < deck.nodes.size(); ++k)
    if (deck.nodes[k].id == deck.nodes[k - 1].id)
      throw ImportError(path + ": node " + std::to_string(deck.nodes[k].id) +
                        " defined twice in *NODE blocks");
  return deck;
}

} // namespace rsi
