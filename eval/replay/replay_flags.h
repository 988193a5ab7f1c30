// The replay outputs a program offers for one episode: --replay FILE.html, --gif FILE.gif,
// --mp4 FILE.mp4 and --frame-stride N, checked before any work and written at the end.
#pragma once

#include <string>

#include "eval/replay/replay.h"

namespace CLI {
class App;
}  // namespace CLI

namespace colav {

class ReplayFlags {
 public:
  /// Adds the flags to `app`.
  explicit ReplayFlags(CLI::App& app);

  /// Whether any replay output was asked for (only then is the episode recorded).
  bool wanted() const { return !page_.empty() || !gif_.empty() || !mp4_.empty(); }

  /// UserError naming the flag for a path that cannot be written, or --mp4 without ffmpeg.
  void Check() const;

  /// Writes every output asked for.
  void Write(const Replay& replay) const;

 private:
  std::string page_;
  std::string gif_;
  std::string mp4_;
  int stride_ = 5;
};

}  // namespace colav
