#include "src/figures/style.h"

#include <array>

#include "src/figures/gnuplot.h"

namespace colav {

std::string FigureColour(std::size_t k) {
  // Colour-blind-safe qualitative palette (Okabe and Ito).
  static const std::array<const char*, 8> kColours = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                      "#e69f00", "#56b4e9", "#000000", "#f0e442"};
  return kColours[k % kColours.size()];
}

std::string LineColour(const std::string& colour) { return "lc rgb " + GnuplotQuote(colour); }

std::string LightGrid() { return "set grid " + LineColour("#dddddd") + "\n"; }

std::string MultiplotLayout(std::int64_t rows, std::int64_t columns, const std::string& title,
                            int title_font_size) {
  std::string layout = "set multiplot layout " + std::to_string(rows) + "," +
                       std::to_string(columns) + " title " + GnuplotQuote(title);
  if (title_font_size > 0) layout += " font '," + std::to_string(title_font_size) + "'";
  return layout + "\n";
}

}  // namespace colav
