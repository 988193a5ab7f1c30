// Animated GIF files of RGB frames, written with giflib. Frames use one fixed 256-colour palette:
// the scene's own colours exactly, then a 6x6x6 colour cube and greys for the anti-aliased
// edges and blends, so a frame's pixels of a scene colour keep that colour exactly.
#pragma once

#include <filesystem>
#include <memory>

#include "eval/replay/scene_frame.h"

struct GifFileType;

namespace colav {

class GifWriter {
 public:
  /// Starts a looping animation of width x height frames shown `delay_cs` hundredths of a second
  /// each; std::runtime_error when the file cannot be written.
  GifWriter(const std::filesystem::path& path, int width, int height, int delay_cs);
  ~GifWriter();
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  /// Appends a frame of the writer's size.
  void Add(const RgbImage& frame);

  /// Ends the file; required for a complete file.
  void Finish();

 private:
  class Palette;

  GifFileType* file_ = nullptr;
  int width_;
  int height_;
  int delay_cs_;
  std::unique_ptr<Palette> palette_;
};

}  // namespace colav
