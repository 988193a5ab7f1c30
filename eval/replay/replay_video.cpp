#include "eval/replay/replay_video.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "eval/replay/gif_file.h"
#include "eval/replay/scene_frame.h"
#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

RgbImage FrameAt(const Replay& replay, int step) {
  return DrawFrame(replay, step, FollowView(replay, 0, step, kVideoFrameSize, kVideoFrameSize));
}

bool FfmpegOnPath() {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path == nullptr ? "" : path);
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(folder) / "ffmpeg";
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error)) return true;
  }
  return false;
}

// Single quotes for the shell ('' inside as '\'').
std::string ShellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::vector<int> FrameSteps(int length, int stride) {
  if (stride < 1) throw std::invalid_argument("frame stride must be at least 1");
  std::vector<int> steps;
  for (int step = 0; step < length; step += stride) steps.push_back(step);
  if (length > 0 && steps.back() != length - 1) steps.push_back(length - 1);
  return steps;
}

void WriteReplayGif(const Replay& replay, const std::filesystem::path& path, int stride) {
  WriteFileAtomically(path, [&](const std::filesystem::path& temporary) {
    GifWriter gif(temporary, kVideoFrameSize, kVideoFrameSize, 100 / kVideoFramesPerSecond);
    for (const int step : FrameSteps(ReplayLength(replay), stride)) gif.Add(FrameAt(replay, step));
    gif.Finish();
  });
}

void RequireFfmpeg(const std::string& flag) {
  if (!FfmpegOnPath()) {
    throw UserError(flag + ": ffmpeg is not on PATH (Debian: apt-get install ffmpeg)");
  }
}

void WriteReplayMp4(const Replay& replay, const std::filesystem::path& path, int stride) {
  RequireFfmpeg("--mp4");
  WriteFileAtomically(path, [&](const std::filesystem::path& temporary) {
    const std::string size = std::to_string(kVideoFrameSize);
    const std::string command =
        "ffmpeg -loglevel error -nostdin -y -f rawvideo -pix_fmt rgb24 -s " + size + "x" + size +
        " -framerate " + std::to_string(kVideoFramesPerSecond) + " -i - -pix_fmt yuv420p -f mp4 " +
        ShellQuoted(temporary.string());
    FILE* pipe = popen(command.c_str(), "w");
    if (pipe == nullptr) throw std::runtime_error("cannot start ffmpeg");
    for (const int step : FrameSteps(ReplayLength(replay), stride)) {
      const RgbImage frame = FrameAt(replay, step);
      std::fwrite(frame.rgb.data(), 1, frame.rgb.size(), pipe);
    }
    if (pclose(pipe) != 0) throw std::runtime_error("ffmpeg failed writing " + path.string());
  });
}

}  // namespace colav
