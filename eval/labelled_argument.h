// Command-line values of the form LABEL=VALUE (plot_training --run, plot_beta_sweep --model).
#pragma once

#include <optional>
#include <string>

namespace colav {

struct LabelledArgument {
  std::optional<std::string> label;  ///< none when the argument has no '='
  std::string value;
};

/// Splits at the first '='. An empty label or value is a UserError naming `flag` and the argument.
LabelledArgument ParseLabelledArgument(const std::string& argument, const std::string& flag);

}  // namespace colav
