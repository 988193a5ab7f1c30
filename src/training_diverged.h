// The trainers' exit statuses besides 0, 1 (a bug) and 2 (bad input), and their guard against NaN
// and infinities (train_ppo, train_vae): a loss or a parameter that
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

/// Exit status of a trainer stopped cleanly on request (SIGINT, SIGTERM) after writing the
/// checkpoint it resumes from: rerun (train_ppo --resume, train_vae the same command) to continue.
/// EX_TEMPFAIL of sysexits.h: a temporary stop, to be retried.
inline constexpr int kStoppedStatus = 75;

}  // namespace colav
