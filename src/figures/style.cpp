#include "eval/figure_colours.h"

#include <array>

namespace colav {

std::string FigureColour(std::size_t k) {
  // Colour-blind-safe qualitative palette (Okabe and Ito).
  static const std::array<const char*, 8> kColours = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                      "#e69f00", "#56b4e9", "#000000", "#f0e442"};
  return kColours[k % kColours.size()];
}

}  // namespace colav
