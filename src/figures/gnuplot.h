// Figures: runs gnuplot on a script and writes a PNG atomically.
#pragma once

#include <filesystem>
#include <string>

namespace colav {

/// Renders `script` (gnuplot commands; inline data blocks welcome) to the PNG `png` with the
/// pngcairo terminal of the given size. The script must not set the terminal or output.
/// UserError when gnuplot is missing or fails (its first error line is included).
void RenderGnuplotPng(const std::string& script, const std::filesystem::path& png, int width = 900,
                      int height = 800);

/// Escapes a string for a gnuplot single-quoted literal.
std::string GnuplotQuote(const std::string& text);

}  // namespace colav
