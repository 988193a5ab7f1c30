#include "eval/replay/replay_flags.h"

#include <CLI/CLI.hpp>

#include "eval/replay/replay_page.h"
#include "eval/replay/replay_video.h"
#include "src/number_flag.h"
#include "src/output_path.h"

namespace colav {

ReplayFlags::ReplayFlags(CLI::App& app) {
  app.add_option(
      "--replay", page_,
      "also write the episode as a replay page (self-contained HTML, open in a browser)");
  app.add_option("--gif", gif_, "also write the episode as an animated GIF (follow view)");
  app.add_option("--mp4", mp4_, "also write the episode as an MP4 video (needs ffmpeg on PATH)");
  AddNumberFlag(app, "--frame-stride", stride_,
                "GIF and MP4: one frame every this many steps (shown at 10 frames/s)", 1, 100000);
}

void ReplayFlags::Check() const {
  if (!page_.empty()) RequireWritableFile(page_, "--replay");
  if (!gif_.empty()) RequireWritableFile(gif_, "--gif");
  if (!mp4_.empty()) {
    RequireWritableFile(mp4_, "--mp4");
    RequireFfmpeg("--mp4");
  }
}

void ReplayFlags::Write(const Replay& replay) const {
  if (!page_.empty()) WriteReplayPage(replay, page_);
  if (!gif_.empty()) WriteReplayGif(replay, gif_, stride_);
  if (!mp4_.empty()) WriteReplayMp4(replay, mp4_, stride_);
}

}  // namespace colav
