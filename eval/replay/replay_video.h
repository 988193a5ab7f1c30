// A replay as moving pictures: an animated GIF (giflib) or an MP4 (raw frames piped to ffmpeg),
// of the follow view of the first run, one frame every `stride` steps.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "eval/replay/replay.h"

namespace colav {

/// Frame size (pixels) and rate (frames per second) of GIF and MP4 files.
inline constexpr int kVideoFrameSize = 480;
inline constexpr int kVideoFramesPerSecond = 10;

/// The steps drawn: 0, stride, 2 stride, ..., and always the last step (the episode's end).
std::vector<int> FrameSteps(int length, int stride);

/// Writes the GIF atomically.
void WriteReplayGif(const Replay& replay, const std::filesystem::path& path, int stride);

/// A colav::UserError naming `flag` when ffmpeg is not on PATH.
void RequireFfmpeg(const std::string& flag);

/// Writes the MP4 (H.264 as ffmpeg's default for .mp4) atomically; ffmpeg must be on PATH.
void WriteReplayMp4(const Replay& replay, const std::filesystem::path& path, int stride);

}  // namespace colav
