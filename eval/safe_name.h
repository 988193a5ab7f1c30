// Model and scenario names end up in CSV cells and file names, so they are kept to a safe
// alphabet.
#pragma once

#include <string>

namespace colav {

/// Throws a UserError "<origin>: name '<name>' ..." unless `name` is non-empty and made of
/// letters, digits, '.', '_' and '-' only.
void RequireSafeName(const std::string& name, const std::string& origin);

}  // namespace colav
