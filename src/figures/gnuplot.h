// Running gnuplot: renders a script to a PNG atomically, and quotes text for its scripts. Every
// figure of the project (env/, train/vae/, eval/) goes through here.
#pragma once

#include <filesystem>
#include <string>

namespace colav {

/// Renders `script` (gnuplot commands; inline data blocks welcome) to the PNG `png` with the
/// pngcairo terminal of the given size in the figure font (src/figures/style.h). The script must
/// not set the terminal or output. UserError when gnuplot is missing or fails (its first error
/// line is included).
void RenderGnuplotPng(const std::string& script, const std::filesystem::path& png, int width = 900,
                      int height = 800);

/// Escapes a string for a gnuplot single-quoted literal.
std::string GnuplotQuote(const std::string& text);

/// `text` with the control characters of gnuplot's enhanced text mode (_ ^ @ & ~ { } \) escaped,
/// for a single-quoted gnuplot string, so it prints literally ('_' would start a subscript).
std::string GnuplotEnhancedText(const std::string& text);

}  // namespace colav
