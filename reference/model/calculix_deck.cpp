#include "calculix_deck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <sstream>

#include "calculix_fields.hpp"
#include "coordinate_entries.hpp"
#include "stream_text.hpp"

namespace rsi {
namespace {

namespace fs = std::filesystem;

/// ccx's limit on nested *INCLUDE (readinput.c: 10 open files).
constexpr int kIncludeDepth = 9;
/// The most ids one GENERATE line may add (400 MB of ids): a bound on
/// memory, far above any deck's node count.
constexpr std::int64_t kGenerateIds = 100000000;

/// A deck line with where it came from, for messages.
struct Where {
  std::string file;
  int line = 0;
  std::string text() const { return file + ":" + std::to_string(line); }
};

/// A significant line (not blank, not a comment, not heading text).
struct Line {
  CalculixLine text;
  Where where;
};

[[noreturn]] void fail(const Where& where, const std::string& what) {
  throw ImportError(where.text() + ": " + what);
}

bool starts_with(const std::string& s, std::string_view prefix) {
  return s.rfind(prefix, 0) == 0;
}

/// ccx's keyword tests (calinput.f), on the upper-case line.
bool is_node_keyword(const std::string& u) {
  return starts_with(u, "*NODE") && !starts_with(u, "*NODEPRINT") &&
         !starts_with(u, "*NODEOUTPUT") && !starts_with(u, "*NODEFILE");
}
bool is_element_keyword(const std::string& u) {
  return starts_with(u, "*ELEMENT") && !starts_with(u, "*ELEMENTOUTPUT");
}

/// The file name of an *INCLUDE line (ccx's includefilename.f): after the
/// line's first '=', to its closing quote if it opens with one, else to
/// the end of the line.
std::string include_name(const CalculixLine& line, const Where& where) {
  const std::string& s = line.upper; // the file name keeps its case there
  const size_t eq = s.find('=');
  if (eq == std::string::npos) fail(where, "*INCLUDE without INPUT=file");
  std::string name;
  if (eq + 1 < s.size() && s[eq + 1] == '"') {
    const size_t close = s.find('"', eq + 2);
    if (close == std::string::npos) fail(where, "*INCLUDE: the file name's closing quote is missing");
    name = s.substr(eq + 2, close - eq - 2);
  } else {
    name = s.substr(eq + 1);
  }
  if (name.empty()) fail(where, "*INCLUDE: the file name is missing");
  if (name.size() > 132)
    fail(where, "*INCLUDE: a file name of more than 132 characters (ccx's limit)");
  return name;
}

/// State of reading the model part across the files it includes.
struct Reader {
  fs::path folder;          ///< ccx's working directory: the deck's folder
  std::ostringstream model; ///< model part, includes inlined
  std::vector<Line> lines;  ///< significant lines of the model part
  bool heading = false;     ///< inside *HEADING's text lines

  /// Reads `path`'s lines until *STEP (returns true) or its end.
  bool read(const fs::path& path, int depth) {
    const std::string text = read_whole_file(path.string());
    size_t offset = 0;
    std::string_view raw;
    int number = 0;
    while (next_line(text, offset, raw)) {
      ++number;
      const Where where{path.string(), number};
      std::string_view kept = raw.substr(0, raw.find('\r'));
      if (kept.size() > kCalculixLineLength)
        fail(where, "a line of " + std::to_string(kept.size()) +
                        " characters: ccx reads at most 1319 a line and would read the rest as "
                        "another line; split it");
      if (heading) {
        if (!kept.empty() && kept[0] == '*' && (kept.size() < 2 || kept[1] != '*')) {
          heading = false;
        } else {
          model << kept << "\n";
          continue;
        }
      }
      CalculixLine line = calculix_line(kept);
      if (line.skipped()) {
        model << kept << "\n";
        continue;
      }
      if (starts_with(line.upper, "*HEADING")) heading = true;
      if (starts_with(line.upper, "*STEP")) return true;
      if (starts_with(line.upper, "*INCLUDE")) {
        const std::string name = include_name(line, where);
        fs::path included(name);
        if (included.is_relative()) included = folder / included;
        if (!fs::is_regular_file(included)) {
          std::string hint;
          const fs::path beside = path.parent_path() / name;
          if (fs::path(name).is_relative() && path.parent_path() != folder &&
              fs::is_regular_file(beside))
            hint = " (ccx opens an included file relative to its working directory, taken as "
                   "the deck's folder " + folder.string() + ", not relative to the including "
                   "file; there is a file " + beside.string() + ": name it relative to " +
                   folder.string() + ")";
          fail(where, "*INCLUDE: the file '" + included.string() + "' does not exist" + hint);
        }
        if (depth + 1 > kIncludeDepth)
          fail(where, "*INCLUDE nested more than 9 deep (ccx's limit; a cycle?)");
        if (read(included, depth + 1)) return true;
        continue;
      }
      model << kept << "\n";
      lines.push_back({std::move(line), where});
    }
    return false;
  }
};

std::vector<std::string> fields_of(const Line& line, const std::string& keyword) {
  const auto fields = calculix_fields(line.text.upper);
  if (!fields)
    fail(line.where, keyword + ": more than 16 fields on a line (ccx's limit); continue on the "
                               "next line");
  return *fields;
}

/// Value of PARAM= on a keyword line, or nullopt.
std::optional<std::string> parameter(const std::vector<std::string>& fields,
                                     const std::string& name) {
  for (size_t i = 1; i < fields.size(); ++i)
    if (starts_with(fields[i], name + "=")) return fields[i].substr(name.size() + 1);
  return std::nullopt;
}

std::string set_name(const std::optional<std::string>& name, const Line& line,
                     const std::string& keyword) {
  if (!name || name->empty()) fail(line.where, keyword + " without NSET=name");
  if (name->size() > 80)
    fail(line.where, keyword + ": a set name of more than 80 characters (ccx's limit)");
  return *name;
}

/// An integer field as ccx reads it (I10), refused where ccx would read
/// it otherwise than written (more than 10 characters) or not at all.
std::int64_t integer_field(const std::string& field, const Line& line, const std::string& what) {
  const std::optional<std::int64_t> value = fortran_integer(field);
  if (field.size() > 10 && fortran_integer(field, std::string::npos) != value)
    fail(line.where, what + " '" + field + "' has more than 10 characters: ccx reads only its "
                            "first 10 ('" + field.substr(0, 10) + "')");
  if (!value)
    fail(line.where, what + " must be an integer in [-2147483648, 2147483647], got '" + field + "'");
  return *value;
}

double real_field(const std::string& field, const Line& line, const std::string& what) {
  const std::optional<double> value = fortran_real(field);
  if (field.size() > 20 && fortran_real(field, std::string::npos) != value)
    fail(line.where, what + " '" + field + "' has more than 20 characters: ccx reads only its "
                            "first 20 ('" + field.substr(0, 20) + "'); shorten it");
  if (!value) fail(line.where, what + " must be a number, got '" + field + "'");
  if (!std::isfinite(*value))
    fail(line.where, what + " must be finite, got '" + field + "'");
  return *value;
}

/// A *NODE block: its data lines into `nodes` (id -> coordinates, the last
/// definition kept) and its set.
void read_node_block(const std::vector<Line>& lines, size_t& k,
                     std::map<int, Eigen::Vector3d>& nodes,
                     std::map<std::string, std::vector<int>>& nsets) {
  const std::vector<std::string> key = fields_of(lines[k], "*NODE");
  const std::optional<std::string> nset = parameter(key, "NSET");
  std::vector<int>* set = nullptr;
  if (nset) set = &nsets[set_name(nset, lines[k], "*NODE, NSET=")];
  for (++k; k < lines.size() && !lines[k].text.keyword(); ++k) {
    const std::vector<std::string> f = fields_of(lines[k], "*NODE");
    const std::int64_t id = integer_field(f[0], lines[k], "*NODE: the node id");
    if (id < 1)
      fail(lines[k].where, "*NODE: node id " + std::to_string(id) +
                               " (ids are integers in [1, 2147483647]; ccx crashes on it)");
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (size_t c = 1; c < std::min<size_t>(f.size(), 4); ++c)
      x(static_cast<int>(c - 1)) = real_field(f[c], lines[k], "*NODE: a coordinate");
    nodes[static_cast<int>(id)] = x;
    if (set) set->push_back(static_cast<int>(id));
  }
}

/// Names of the node sets an *NSET block defines, with where, to tell a
/// set named before its definition (ccx silently reads it as empty) from
/// one never defined.
std::map<std::string, Where> later_sets(const std::vector<Line>& lines) {
  std::map<std::string, Where> defined;
  for (const Line& line : lines)
    if (starts_with(line.text.upper, "*NSET")) {
      const auto fields = calculix_fields(line.text.upper);
      if (!fields) continue;
      const std::optional<std::string> name = parameter(*fields, "NSET");
      if (name && !defined.count(*name)) defined[*name] = line.where;
    }
  return defined;
}

void read_nset_block(const std::vector<Line>& lines, size_t& k, int largest,
                     const std::map<std::string, Where>& definitions,
                     std::map<std::string, std::vector<int>>& nsets,
                     std::map<std::string, std::vector<int>>& dropped) {
  const Line& head = lines[k];
  const std::vector<std::string> key = fields_of(head, "*NSET");
  const std::string name = set_name(parameter(key, "NSET"), head, "*NSET");
  const bool generate = std::any_of(key.begin() + 1, key.end(), [](const std::string& f) {
    return starts_with(f, "GENERATE");
  });
  // The set's earlier content, before this block adds to it.
  std::vector<int> set = nsets.count(name) ? nsets[name] : std::vector<int>{};
  for (++k; k < lines.size() && !lines[k].text.keyword(); ++k) {
    const Line& line = lines[k];
    const std::vector<std::string> f = fields_of(line, "*NSET");
    if (generate) {
      if (f.size() < 2 || f[1].empty())
        fail(line.where, "*NSET, GENERATE: a line is 'first, last[, step]' (ccx crashes on "
                         "fewer fields)");
      const std::int64_t first = integer_field(f[0], line, "*NSET, GENERATE: first");
      std::int64_t last = integer_field(f[1], line, "*NSET, GENERATE: last");
      const std::int64_t step =
          f.size() >= 3 && !f[2].empty() ? integer_field(f[2], line, "*NSET, GENERATE: step") : 1;
      if (first < 1 || first > largest)
        fail(line.where, "*NSET, GENERATE: first = " + std::to_string(first) +
                             " must lie in [1, " + std::to_string(largest) +
                             "], the largest node id (ccx refuses it)");
      if (last < first)
        fail(line.where, "*NSET, GENERATE: last = " + std::to_string(last) +
                             " is below first = " + std::to_string(first) +
                             " (ccx's reading of it is not defined)");
      if (step < 1)
        fail(line.where, "*NSET, GENERATE: step = " + std::to_string(step) +
                             " must be at least 1 (ccx refuses or crashes on it)");
      last = std::min<std::int64_t>(last, largest); // ccx: "end value > nk, replaced by nk"
      const std::int64_t count = (last - first) / step + 1;
      if (count > kGenerateIds)
        fail(line.where, "*NSET, GENERATE: " + std::to_string(count) +
                             " ids in one line, more than the 100000000 rsi holds");
      for (std::int64_t id = first; id <= last; id += step)
        set.push_back(static_cast<int>(id));
      continue;
    }
    for (size_t i = 0; i < f.size(); ++i) {
      if (f[i].empty())
        fail(line.where, "*NSET: an empty field between two commas (ccx reads it as node 0 and "
                         "crashes)");
      if (fortran_integer(f[i])) {
        const std::int64_t id = integer_field(f[i], line, "*NSET: a node id");
        if (id < 1)
          fail(line.where, "*NSET: node id " + std::to_string(id) +
                               " (ids are integers in [1, 2147483647])");
        if (id <= largest) set.push_back(static_cast<int>(id));
        else dropped[name].push_back(static_cast<int>(id)); // ccx drops ids above nk
        continue;
      }
      if (f[i].size() > 80)
        fail(line.where, "*NSET: a set name of more than 80 characters (ccx's limit)");
      if (f[i] == name) continue; // ccx: a set naming itself adds nothing
      const auto found = nsets.find(f[i]);
      if (found != nsets.end()) {
        set.insert(set.end(), found->second.begin(), found->second.end());
        continue;
      }
      const auto later = definitions.find(f[i]);
      if (later != definitions.end())
        fail(line.where, "*NSET " + name + " names the node set " + f[i] +
                             " before it is defined (" + later->second.text() +
                             "): ccx reads that name as an empty set; define " + f[i] + " first");
      fail(line.where, "*NSET " + name + ": node set " + f[i] +
                           " is not defined (a node set of *NSET or *NODE, NSET=)");
    }
  }
  nsets[name] = std::move(set);
}

/// A *ELEMENT block of type C3D10: its elements, each id and 10 nodes,
/// continued on the next line when a line holds fewer (ccx reads on).
void read_tetrahedron_block(const std::vector<Line>& lines, size_t& k,
                            std::vector<DeckTetrahedron>& tetrahedra) {
  DeckTetrahedron e;
  int have = -1; // fields of the current element read: -1 before its id
  for (++k; k < lines.size() && !lines[k].text.keyword(); ++k) {
    for (const std::string& field : fields_of(lines[k], "*ELEMENT")) {
      if (field.empty()) continue;
      const std::int64_t value = integer_field(field, lines[k], "*ELEMENT, TYPE=C3D10: an id");
      if (value < 1 || value > 2147483647)
        fail(lines[k].where, "*ELEMENT, TYPE=C3D10: id " + std::to_string(value) +
                                 " (ids are integers in [1, 2147483647])");
      if (have < 0) e.id = static_cast<int>(value);
      else e.nodes[static_cast<size_t>(have)] = static_cast<int>(value);
      if (++have == 10) {
        tetrahedra.push_back(e);
        have = -1;
      }
    }
  }
  if (have >= 0)
    fail(lines[k - 1].where, "*ELEMENT, TYPE=C3D10: element " + std::to_string(e.id) + " has " +
                                 std::to_string(have) + " nodes, 10 needed");
}

/// A *SURFACE block of TYPE=ELEMENT (the default): lines "element, Sk".
void read_element_surface_block(const std::vector<Line>& lines, size_t& k,
                                const std::string& name, CalculixDeck& deck) {
  std::vector<DeckElementFace>& faces = deck.element_surfaces[name];
  for (++k; k < lines.size() && !lines[k].text.keyword(); ++k) {
    // ccx is the judge of the deck: a line this reader does not take
    // (an elset, a shell's SPOS, an edge) is noted, and refused only by
    // the contact surface that would need it.
    const std::optional<std::vector<std::string>> f = calculix_fields(lines[k].text.upper);
    const std::optional<std::int64_t> element =
        f && f->size() >= 2 ? fortran_integer((*f)[0]) : std::nullopt;
    const std::string label = f && f->size() >= 2 ? (*f)[1] : "";
    const int face = label.size() == 2 && label[0] == 'S' ? label[1] - '0' : 0;
    if (!element || *element < 1 || *element > 2147483647 || face < 1 || face > 6) {
      deck.surfaces_not_read.emplace(name, lines[k].where.text());
      continue;
    }
    faces.push_back({static_cast<int>(*element), face});
  }
}

void note(std::vector<DeckKeyword>& list, const std::string& name, const Where& where) {
  if (std::none_of(list.begin(), list.end(),
                   [&](const DeckKeyword& k) { return k.name == name; }))
    list.push_back({name, where.text()});
}

} // namespace

CalculixDeck read_calculix_deck(const std::string& path) {
  CalculixDeck deck;
  deck.path = path;
  Reader reader;
  reader.folder = fs::path(path).parent_path();
  if (reader.folder.empty()) reader.folder = ".";
  reader.read(fs::path(path), 0);
  deck.model_text = stream_text(reader.model);
  const std::vector<Line>& lines = reader.lines;

  // Keywords and element types, for the features rsi takes.
  for (const Line& line : lines) {
    if (!line.text.keyword()) continue;
    const auto fields = calculix_fields(line.text.upper);
    const std::string name = fields ? fields->front().substr(1) : line.text.upper.substr(1);
    note(deck.keywords, name, line.where);
    if (is_element_keyword(line.text.upper) && fields)
      if (const std::optional<std::string> type = parameter(*fields, "TYPE"))
        note(deck.element_types, *type, line.where);
    if (fields && (name == "SOLIDSECTION" || name == "SHELLSECTION" || name == "BEAMSECTION"))
      if (const std::optional<std::string> elset = parameter(*fields, "ELSET"))
        note(deck.section_elsets, *elset, line.where);
  }

  // ccx reads every *NODE block before any *NSET (keystart.f).
  std::map<int, Eigen::Vector3d> nodes;
  for (size_t k = 0; k < lines.size();)
    if (is_node_keyword(lines[k].text.upper)) read_node_block(lines, k, nodes, deck.nsets);
    else ++k;
  deck.largest_node_id = nodes.empty() ? 0 : nodes.rbegin()->first;
  const std::map<std::string, Where> definitions = later_sets(lines);
  for (size_t k = 0; k < lines.size();) {
    if (starts_with(lines[k].text.upper, "*NSET")) {
      // Sets defined from here on are not yet defined for this block.
      std::map<std::string, Where> later;
      for (const auto& [name, where] : definitions)
        if (!deck.nsets.count(name)) later.insert({name, where});
      read_nset_block(lines, k, deck.largest_node_id, later, deck.nsets, deck.dropped_ids);
    } else {
      ++k;
    }
  }
  for (const auto& [id, x] : nodes)
    deck.nodes.push_back({id, x});

  // The C3D10 elements and the element surfaces, for contact surfaces.
  for (size_t k = 0; k < lines.size();) {
    const std::string& u = lines[k].text.upper;
    const auto fields = lines[k].text.keyword() ? calculix_fields(u) : std::nullopt;
    if (fields && is_element_keyword(u) && parameter(*fields, "TYPE") == "C3D10") {
      read_tetrahedron_block(lines, k, deck.tetrahedra);
    } else if (fields && fields->front() == "*SURFACE" &&
               parameter(*fields, "TYPE").value_or("ELEMENT") == "ELEMENT") {
      const std::optional<std::string> name = parameter(*fields, "NAME");
      if (!name || name->empty()) fail(lines[k].where, "*SURFACE without NAME=name");
      read_element_surface_block(lines, k, *name, deck);
    } else {
      ++k;
    }
  }
  return deck;
}

} // namespace rsi
