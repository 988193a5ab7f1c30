#include "eval/labelled_argument.h"

#include "src/error.h"

namespace colav {

LabelledArgument ParseLabelledArgument(const std::string& argument, const std::string& flag) {
  const std::size_t equals = argument.find('=');
  LabelledArgument parsed;
  if (equals == std::string::npos) {
    parsed.value = argument;
  } else {
    parsed.label = argument.substr(0, equals);
    parsed.value = argument.substr(equals + 1);
  }
  if ((parsed.label && parsed.label->empty()) || parsed.value.empty()) {
    throw UserError(flag + " '" + argument + "': expected LABEL=VALUE");
  }
  return parsed;
}

}  // namespace colav
