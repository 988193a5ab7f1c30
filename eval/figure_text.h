// Text for gnuplot's enhanced mode (PlotScene's titles and keys): '_' would start a subscript.
#pragma once

#include <string>

namespace colav {

/// `text` with gnuplot's enhanced-text control characters (_ ^ @ & ~ { } \) escaped, for a
/// single-quoted gnuplot string, so it prints literally.
std::string GnuplotEnhancedText(const std::string& text);

}  // namespace colav
