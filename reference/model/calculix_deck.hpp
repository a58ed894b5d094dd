#pragma once
// What rsi reads of a CalculiX input deck, read as ccx 2.20 reads it
// (calculix_fields.hpp: blanks removed, upper case, fields, Fortran
// numbers): its model part (every line before the first *STEP, each
// *INCLUDE replaced by the file it names), the node coordinates of its
// *NODE blocks, its node sets (*NODE, NSET= and *NSET) and the element
// types and keywords it uses.
//
//   - *INCLUDE, INPUT=name: ccx opens `name` relative to its working
//     directory, for every include however deep; rsi takes the deck's own
//     folder as that directory (ccx run beside the deck, as the rotor37
//     README does), not the including file's folder. At most 9 levels
//     deep (ccx's limit). A quoted name ("a,b.inp") is read to its quote.
//   - *NODE: "id[, x[, y[, z]]]": an id alone is at (0, 0, 0), an empty
//     coordinate is 0, fields after the fourth are ignored; an id is an
//     integer of at most 10 characters in [1, 2147483647], a coordinate a
//     Fortran real of which ccx reads the first 20 characters. A node
//     defined twice takes its last definition, as in ccx.
//   - node sets: every *NODE block is read before any *NSET (ccx's order),
//     so *NODE, NSET=X fills X first. *NSET, NSET=X lists node ids and
//     names of node sets defined before it (their nodes, in order; X
//     itself adds nothing), a trailing comma allowed; an id above the
//     largest node id is dropped (ccx warns and drops it; kept in
//     dropped_ids). *NSET X again appends. GENERATE: "first, last[, step]", first in [1, the largest
//     node id], last at least first and clamped to the largest node id,
//     step >= 1, in 64-bit arithmetic; ids need not be defined nodes.
//   - refused (ImportError naming file, line and keyword; ccx crashes or
//     silently reads something else on each): a line over 1319 characters
//     or of more than 16 fields, an id field of more than 10 characters or
//     a coordinate of more than 20 that reads otherwise when cut there, a
//     node id outside [1, 2147483647], an empty field inside an *NSET
//     list, a set named before it is defined (ccx reads it as empty),
//     GENERATE with first > last, step < 1 or fewer than two fields, a
//     GENERATE range of more than 100,000,000 ids, an *INCLUDE without a
//     file name or of a missing file, *NSET without NSET=, a set name over
//     80 characters, a non-finite coordinate.
// Keywords are recognised by their leading characters, as ccx does
// (*NODE but not *NODE PRINT, *NODE FILE, *NODE OUTPUT; *ELEMENT but not
// *ELEMENT OUTPUT); "**" lines are comments; *HEADING's lines are text.

#include <array>
#include <map>
#include <string>
#include <vector>

#include "component.hpp"

namespace rsi {

/// A keyword of the deck and where it first appears.
struct DeckKeyword {
  std::string name;  ///< upper case, blanks removed, without '*' (e.g. "CONTACTPAIR")
  std::string where; ///< "file:line"
};

/// A quadratic tetrahedron (C3D10) as the deck lists it: corners 1-4, then
/// the midside nodes of edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4 (ccx's order).
struct DeckTetrahedron {
  int id = 0;
  std::array<int, 10> nodes{};
};

/// One face of an element surface (*SURFACE, TYPE=ELEMENT): the element and
/// its face label S1 .. S4 as 1 .. 4.
struct DeckElementFace {
  int element = 0;
  int face = 0;
};

struct CalculixDeck {
  std::string path;                              ///< the deck as named
  std::string model_text;                        ///< model part, includes inlined
  std::vector<ComponentNode> nodes;              ///< ascending id
  int largest_node_id = 0;                       ///< ccx's nk: the largest id of a *NODE line
  std::map<std::string, std::vector<int>> nsets; ///< upper-case name -> node ids, in order
  /// Per set, the ids its *NSET lines list above the largest node id,
  /// which ccx drops (with a warning) and so does `nsets`: a boundary set
  /// holding one is refused (component_case.hpp), not silently shortened.
  std::map<std::string, std::vector<int>> dropped_ids;
  std::vector<DeckKeyword> keywords;             ///< each keyword once, first appearance first
  std::vector<DeckKeyword> element_types;        ///< each *ELEMENT TYPE= once (name = the type)
  /// The ELSET= of each *SOLID SECTION, *SHELL SECTION and *BEAM SECTION,
  /// once each (upper case): the elements that carry a material and so a
  /// mass, which a centrifugal load (*DLOAD ... CENTRIF) must name.
  std::vector<DeckKeyword> section_elsets;
  /// The C3D10 elements, in the deck's order (other types are not kept:
  /// their faces are not read).
  std::vector<DeckTetrahedron> tetrahedra;
  /// *SURFACE, TYPE=ELEMENT (the default type), by upper-case name: the
  /// faces its lines list as "element id, S1 .. S6". A line of another
  /// form (an *ELSET name, a shell's SPOS, an edge) is not read: the
  /// first such line of each surface is in `surfaces_not_read` (the
  /// contact surface refuses such a surface, saying where).
  std::map<std::string, std::vector<DeckElementFace>> element_surfaces;
  std::map<std::string, std::string> surfaces_not_read; ///< surface -> "file:line"
};

CalculixDeck read_calculix_deck(const std::string& path);

} // namespace rsi
