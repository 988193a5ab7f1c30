// The look shared by every figure (the scene plot in env/, the VAE figures in train/vae/, the
// evaluation figures in eval/): one font, one palette for compared runs, one light grid, one way
// to title a grid of panels. Colours with a meaning in a single figure stay with that figure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace colav {

/// The font of every figure (gnuplot "name,size"); a multiplot title may be larger.
inline constexpr const char* kFigureFont = "Sans,10";

/// Colour k ("#rrggbb") of a fixed qualitative palette, repeating after eight: the lines of the
/// figures that compare several runs or models.
std::string FigureColour(std::size_t k);

/// Gnuplot line colour `lc rgb '<colour>'` of a colour "#rrggbb" or a gnuplot colour name.
std::string LineColour(const std::string& colour);

/// The light background grid of the Cartesian figures: "set grid ...\n".
std::string LightGrid();

/// "set multiplot layout ROWS,COLUMNS title 'TITLE'\n": a figure of panels under one title, which
/// is `title_font_size` points large when positive (else in the figure font's size).
std::string MultiplotLayout(std::int64_t rows, std::int64_t columns, const std::string& title,
                            int title_font_size = 0);

}  // namespace colav
