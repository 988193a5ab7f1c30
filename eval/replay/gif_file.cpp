#include "eval/replay/gif_file.h"

#include <fcntl.h>
#include <gif_lib.h>
#include <unistd.h>

#include <array>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace colav {
namespace {

constexpr int kPaletteSize = 256;
constexpr int kCubeLevels = 6;

std::runtime_error GifError(const std::string& what, int code) {
  return std::runtime_error("GIF: " + what + ": " + GifErrorString(code));
}

}  // namespace

// The fixed palette and the nearest entry of each colour met so far (frames have a few
// thousand distinct colours, so the search runs once per colour, not per pixel).
class GifWriter::Palette {
 public:
  Palette() {
    for (const FrameColour& c : {kBackgroundColour, kPathColour, kLookAheadColour, kCircleColour,
                                 kObstacleColour, kRangeColour, kOutlineColour, kCollisionColour}) {
      Add(c.r, c.g, c.b);
    }
    for (const FrameColour& c : kRunColours) Add(c.r, c.g, c.b);
    Add(255, 255, 255);
    for (int r = 0; r < kCubeLevels; ++r) {
      for (int g = 0; g < kCubeLevels; ++g) {
        for (int b = 0; b < kCubeLevels; ++b) Add(51 * r, 51 * g, 51 * b);
      }
    }
    const int greys = kPaletteSize - size_;
    for (int k = 1; k <= greys; ++k) {
      const int grey = 255 * k / (greys + 1);
      Add(grey, grey, grey);
    }
  }

  const std::array<GifColorType, kPaletteSize>& colours() const { return colours_; }

  GifByteType IndexOf(const std::uint8_t* rgb) {
    const std::uint32_t key = rgb[0] << 16 | rgb[1] << 8 | rgb[2];
    const auto found = nearest_.find(key);
    if (found != nearest_.end()) return found->second;
    int best = 0;
    int best_distance = 1 << 30;
    for (int i = 0; i < kPaletteSize; ++i) {
      const int dr = colours_[i].Red - rgb[0];
      const int dg = colours_[i].Green - rgb[1];
      const int db = colours_[i].Blue - rgb[2];
      const int distance = dr * dr + dg * dg + db * db;
      if (distance < best_distance) {
        best = i;
        best_distance = distance;
      }
    }
    return nearest_[key] = static_cast<GifByteType>(best);
  }

 private:
  void Add(int r, int g, int b) {
    colours_[size_++] = {static_cast<GifByteType>(r), static_cast<GifByteType>(g),
                         static_cast<GifByteType>(b)};
  }

  std::array<GifColorType, kPaletteSize> colours_{};
  int size_ = 0;
  std::unordered_map<std::uint32_t, GifByteType> nearest_;
};

GifWriter::GifWriter(const std::filesystem::path& path, int width, int height, int delay_cs)
    : width_(width), height_(height), delay_cs_(delay_cs), palette_(std::make_unique<Palette>()) {
  // Created as other outputs are (0666 less the umask; giflib's own open would make it 0600).
  const int descriptor = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
  if (descriptor < 0) throw std::runtime_error("GIF: cannot create " + path.string());
  int error = 0;
  file_ = EGifOpenFileHandle(descriptor, &error);
  if (file_ == nullptr) {
    close(descriptor);
    throw GifError(path.string(), error);
  }
  EGifSetGifVersion(file_, true);  // GIF89a: frame delays and looping
  ColorMapObject* map = GifMakeMapObject(kPaletteSize, palette_->colours().data());
  const int status = EGifPutScreenDesc(file_, width, height, 8, 0, map);
  GifFreeMapObject(map);
  if (status == GIF_ERROR) throw GifError("screen", file_->Error);
  // The NETSCAPE2.0 application block: loop forever.
  const GifByteType loop[] = {1, 0, 0};
  if (EGifPutExtensionLeader(file_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
      EGifPutExtensionBlock(file_, 11, "NETSCAPE2.0") == GIF_ERROR ||
      EGifPutExtensionBlock(file_, 3, loop) == GIF_ERROR ||
      EGifPutExtensionTrailer(file_) == GIF_ERROR) {
    throw GifError("loop extension", file_->Error);
  }
}

GifWriter::~GifWriter() {
  if (file_ != nullptr) EGifCloseFile(file_, nullptr);
}

void GifWriter::Add(const RgbImage& frame) {
  if (frame.width != width_ || frame.height != height_) {
    throw std::invalid_argument("GIF: frame of " + std::to_string(frame.width) + "x" +
                                std::to_string(frame.height) + " in an animation of " +
                                std::to_string(width_) + "x" + std::to_string(height_));
  }
  GraphicsControlBlock control{DISPOSAL_UNSPECIFIED, false, delay_cs_, NO_TRANSPARENT_COLOR};
  GifByteType extension[4];
  EGifGCBToExtension(&control, extension);
  if (EGifPutExtension(file_, GRAPHICS_EXT_FUNC_CODE, 4, extension) == GIF_ERROR ||
      EGifPutImageDesc(file_, 0, 0, width_, height_, false, nullptr) == GIF_ERROR) {
    throw GifError("frame", file_->Error);
  }
  std::vector<GifByteType> row(width_);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) row[x] = palette_->IndexOf(&frame.rgb[3 * (y * width_ + x)]);
    if (EGifPutLine(file_, row.data(), width_) == GIF_ERROR) throw GifError("row", file_->Error);
  }
}

void GifWriter::Finish() {
  int error = 0;
  const int status = EGifCloseFile(file_, &error);
  file_ = nullptr;
  if (status == GIF_ERROR) throw GifError("closing", error);
}

}  // namespace colav
