#pragma once
// What rsi reads of a CalculiX input deck: its model part (every line
// before the first *STEP, with each *INCLUDE replaced by the file it names,
// resolved against the including file's folder), the node coordinates of
// its *NODE blocks and the node sets of its *NSET blocks (plain lists and
// GENERATE). Keywords are case-insensitive, "**" lines are comments.
// Throws ImportError naming the file and line of a malformed line or a
// missing included file.

#include <map>
#include <string>
#include <vector>

#include "component.hpp"

namespace rsi {

struct CalculixDeck {
  std::string path;                              ///< the deck as named
  std::string model_text;                        ///< model part, includes inlined
  std::vector<ComponentNode> nodes;              ///< ascending id
  std::map<std::string, std::vector<int>> nsets; ///< upper-case name -> node ids, in order
};

CalculixDeck read_calculix_deck(const std::string& path);

} // namespace rsi
