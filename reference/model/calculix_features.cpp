#include "calculix_features.hpp"

#include <string_view>

namespace rsi {
namespace {

struct Refused {
  std::string_view name;   ///< as ccx reads it: upper case, no blanks
  std::string_view shown;  ///< as a user writes it
  std::string_view reason; ///< why, and what to use instead
  bool prefix = false;     ///< a family of names (the element types DC3D8, DC2D4, ...)
};

constexpr Refused kKeywords[] = {
    {"CONTACTPAIR", "*CONTACT PAIR",
     "contact is not linear: in the linear model rsi takes ccx leaves the pair open (no "
     "stiffness across the surfaces); tie the surfaces (*TIE) for a bonded contact, or remove "
     "the pair (rsi's rubbing models the casing contact)"},
    {"CYCLICSYMMETRYMODEL", "*CYCLIC SYMMETRY MODEL",
     "rsi takes the whole component, and a sector's matrices are not it: give the full model "
     "(expand the sector, e.g. with cgx)"},
    {"DASHPOT", "*DASHPOT",
     "a dashpot is not part of K or M: remove it and give the component's damping in the case "
     "(damping.rayleigh or damping.modal_ratio)"},
    {"DAMPING", "*DAMPING",
     "material damping is not part of K or M: remove it and give the component's damping in "
     "the case (damping.rayleigh or damping.modal_ratio)"},
};

constexpr std::string_view kHeat =
    "rsi takes structural elements: use the structural element of the same shape (C3D8 for "
    "DC3D8, CPS4 for DC2D4, CAX4 for DCAX4)";

constexpr Refused kElements[] = {
    {"DC3D", "heat transfer", kHeat, true},
    {"DC2D", "heat transfer", kHeat, true},
    {"DCAX", "heat transfer", kHeat, true},
    {"D", "fluid network", "rsi takes structural elements; remove the network"},
    {"F3D", "fluid", "rsi takes structural elements; remove the fluid", true},
    {"GAPUNI", "gap",
     "a gap is not linear: ccx leaves it open in the linear model; use a spring (SPRINGA) for a "
     "closed gap, or remove it", true},
    {"DASHPOTA", "dashpot",
     "a dashpot is not part of K or M: remove it and give the component's damping in the case "
     "(damping.rayleigh or damping.modal_ratio)"},
};

bool matches(const Refused& r, const std::string& name) {
  return r.prefix ? name.rfind(r.name, 0) == 0 : name == r.name;
}

} // namespace

void check_calculix_features(const CalculixDeck& deck) {
  for (const DeckKeyword& k : deck.keywords)
    for (const Refused& r : kKeywords)
      if (matches(r, k.name))
        throw ImportError(k.where + ": " + std::string(r.shown) + ": " + std::string(r.reason));
  for (const DeckKeyword& e : deck.element_types)
    for (const Refused& r : kElements)
      if (matches(r, e.name))
        throw ImportError(e.where + ": element type " + e.name + " (" + std::string(r.shown) +
                          "): " + std::string(r.reason));
}

} // namespace rsi
