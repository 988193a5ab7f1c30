// Distinct line colours for the figures that compare several runs or models.
#pragma once

#include <cstddef>
#include <string>

namespace colav {

/// Colour k ("#rrggbb") of a fixed qualitative palette, repeating after eight.
std::string FigureColour(std::size_t k);

}  // namespace colav
