#include "eval/figure_text.h"

namespace colav {

std::string GnuplotEnhancedText(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (std::string("_^@&~{}\\").find(c) != std::string::npos) escaped += '\\';
    escaped += c;
  }
  return escaped;
}

}  // namespace colav
