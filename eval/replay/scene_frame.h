// A replay's scene at one step drawn with Cairo into an RGB image: the frames of GIF and MP4
// files and the Python environment's render(). It draws what the replay page draws, with the
// same colours and view transform (eval/replay/replay_page.html), apart from the page's panel.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "eval/replay/replay.h"

namespace colav {

/// World point (x, y) (m) is drawn at pixel (width/2 + (x - center_x) * scale,
/// height/2 - (y - center_y) * scale).
struct FrameView {
  double center_x = 0;
  double center_y = 0;
  double scale = 1;  ///< pixels per metre
  int width = 480;
  int height = 480;
};

/// The page's follow view: centred on run `run`'s vessel at `step`, 300 m across the width.
FrameView FollowView(const Replay& replay, int run, int step, int width, int height);

/// Pixel of a world point under the view.
std::array<double, 2> PixelOf(const FrameView& view, double x, double y);

/// Rows of RGB pixels, top row first.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< 3 bytes per pixel
};

/// The scene at `step` (each run at its last step if it ended earlier), with the rays of run
/// `rays_of_run` (-1: none) and a caption line (scene name, step).
RgbImage DrawFrame(const Replay& replay, int step, const FrameView& view, int rays_of_run = 0);

/// The colours frames are drawn with (RGB), shared with the replay page.
struct FrameColour {
  std::uint8_t r, g, b;
};
inline constexpr FrameColour kBackgroundColour = {0xee, 0xf3, 0xf8};
inline constexpr FrameColour kPathColour = {0x83, 0x95, 0xa7};
inline constexpr FrameColour kLookAheadColour = {0xe6, 0x7e, 0x22};
inline constexpr FrameColour kCircleColour = {0x5d, 0x6d, 0x7e};
inline constexpr FrameColour kObstacleColour = {0xc0, 0x39, 0x2b};
inline constexpr FrameColour kRangeColour = {0xb8, 0xc7, 0xd6};
inline constexpr FrameColour kOutlineColour = {0x1b, 0x26, 0x31};
inline constexpr FrameColour kCollisionColour = {0xd6, 0x27, 0x28};
/// Run k is drawn in kRunColours[k % 6].
inline constexpr std::array<FrameColour, 6> kRunColours = {{{0x1f, 0x77, 0xb4},
                                                            {0x8e, 0x44, 0xad},
                                                            {0x27, 0xae, 0x60},
                                                            {0xd4, 0xac, 0x0d},
                                                            {0x17, 0xa5, 0xb8},
                                                            {0x6e, 0x4b, 0x3a}}};

}  // namespace colav
