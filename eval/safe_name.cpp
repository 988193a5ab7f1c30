#include "eval/safe_name.h"

#include <algorithm>
#include <cctype>

#include "src/error.h"

namespace colav {

void RequireSafeName(const std::string& name, const std::string& origin) {
  const bool safe = !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) != 0 || c == '.' || c == '_' || c == '-';
  });
  if (!safe) {
    throw UserError(origin + ": name '" + name +
                    "' may only contain letters, digits, '.', '_' and '-'");
  }
}

}  // namespace colav
