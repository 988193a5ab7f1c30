// The trainers' guard against NaN and infinities (train_ppo, train_vae): a loss or a parameter that
// is no longer finite stops training before it reaches a checkpoint, so the last good checkpoint
// is kept, and the program exits with kDivergedStatus after one line naming the cause.
#pragma once

#include <stdexcept>

namespace colav {

/// A loss or a parameter became NaN or infinite: training cannot go on.
class TrainingDiverged : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Exit status of a trainer stopped by TrainingDiverged.
inline constexpr int kDivergedStatus = 3;

}  // namespace colav
