#include "eval/replay/scene_frame.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "env/angles.h"
#include "env/range_finder.h"
#include "env/vessel_model.h"

namespace colav {
namespace {

// As the page: metres across the follow view, hulls enlarged to a visible width, rays.
constexpr double kFollowWidth = 300.0;
constexpr double kMinHullWidthPixels = 8.0;
constexpr double kHeadingLinePixels = 24.0;

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void SetColour(cairo_t* cr, FrameColour colour, double alpha = 1.0) {
  cairo_set_source_rgba(cr, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0, alpha);
}

void MoveOrLine(cairo_t* cr, bool first, const std::array<double, 2>& p) {
  if (first) {
    cairo_move_to(cr, p[0], p[1]);
  } else {
    cairo_line_to(cr, p[0], p[1]);
  }
}

// Pentagon hull (env/obstacles.cpp VesselHull) of width w, enlarged to kMinHullWidthPixels.
void HullPath(cairo_t* cr, const FrameView& view, const ReplayPose& pose, double width) {
  const double h = std::max(width, kMinHullWidthPixels / view.scale) / 2.0;
  const double local[5][2] = {{-h, -h}, {-h, h}, {h, h}, {3.0 * h, 0.0}, {h, -h}};
  const double c = std::cos(pose.heading);
  const double s = std::sin(pose.heading);
  cairo_new_path(cr);
  for (int k = 0; k < 5; ++k) {
    const double u = local[k][0];
    const double v = local[k][1];
    MoveOrLine(cr, k == 0, PixelOf(view, pose.x + c * u - s * v, pose.y + s * u + c * v));
  }
  cairo_close_path(cr);
}

void FillAndOutline(cairo_t* cr, FrameColour fill) {
  SetColour(cr, fill);
  cairo_fill_preserve(cr);
  SetColour(cr, kOutlineColour);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
}

void DrawPathAndObstacles(cairo_t* cr, const ReplayScene& scene, int step, const FrameView& view) {
  SetColour(cr, kPathColour);
  cairo_set_line_width(cr, 2.0);
  for (std::size_t i = 0; i < scene.path.size(); ++i) {
    MoveOrLine(cr, i == 0, PixelOf(view, scene.path[i].x, scene.path[i].y));
  }
  cairo_stroke(cr);
  SetColour(cr, kCircleColour);
  for (const ReplayCircle& circle : scene.circles) {
    const auto p = PixelOf(view, circle.x, circle.y);
    cairo_new_sub_path(cr);
    cairo_arc(cr, p[0], p[1], std::max(1.5, circle.radius * view.scale), 0, 2 * kPi);
  }
  cairo_fill(cr);
  if (scene.vessel_poses.empty()) return;
  const auto& poses =
      scene.vessel_poses[std::min<std::size_t>(step, scene.vessel_poses.size() - 1)];
  for (std::size_t k = 0; k < poses.size(); ++k) {
    HullPath(cr, view, poses[k], scene.vessel_widths[k]);
    FillAndOutline(cr, kObstacleColour);
  }
}

// Closeness of a ray with a return: yellow (far) to red (contact).
void SetRayColour(cairo_t* cr, std::uint8_t closeness) {
  const double t = closeness / 255.0;
  cairo_set_source_rgba(cr, std::round(241 - 30 * t) / 255.0, std::round(196 - 170 * t) / 255.0,
                        std::round(15 + 20 * t) / 255.0, 0.85);
}

// The rays that return, inside a circle of the sensor's range.
void DrawRays(cairo_t* cr, const ReplayStep& step, const FrameView& view) {
  const auto origin = PixelOf(view, step.pose.x, step.pose.y);
  cairo_set_line_width(cr, 1.0);
  SetColour(cr, kRangeColour);
  cairo_arc(cr, origin[0], origin[1], RangeFinder::kRange * view.scale, 0, 2 * kPi);
  cairo_stroke(cr);
  for (int i = 0; i < kNumRays; ++i) {
    if (step.closeness[i] == 0) continue;
    const double angle = step.pose.heading - kPi + (i + 1) * RangeFinder::kRaySpacing;
    const double range = RangeOfClosenessByte(step.closeness[i]);
    const auto end =
        PixelOf(view, step.pose.x + range * std::cos(angle), step.pose.y + range * std::sin(angle));
    SetRayColour(cr, step.closeness[i]);
    cairo_move_to(cr, origin[0], origin[1]);
    cairo_line_to(cr, end[0], end[1]);
    cairo_stroke(cr);
  }
}

void DrawLookAheadPoint(cairo_t* cr, const ReplayStep& step, const FrameView& view) {
  const auto p = PixelOf(view, step.look_ahead_point.x, step.look_ahead_point.y);
  SetColour(cr, kLookAheadColour);
  cairo_arc(cr, p[0], p[1], 4.0, 0, 2 * kPi);
  cairo_fill(cr);
}

void DrawRun(cairo_t* cr, const ReplayRun& run, int last, FrameColour colour,
             const FrameView& view) {
  SetColour(cr, colour, 0.6);
  cairo_set_line_width(cr, 2.0);
  for (int j = 0; j <= last; ++j) {
    MoveOrLine(cr, j == 0, PixelOf(view, run.steps[j].pose.x, run.steps[j].pose.y));
  }
  cairo_stroke(cr);
  const ReplayStep& step = run.steps[last];
  const auto p = PixelOf(view, step.pose.x, step.pose.y);
  SetColour(cr, kOutlineColour);
  cairo_set_line_width(cr, 1.5);
  cairo_move_to(cr, p[0], p[1]);
  cairo_line_to(cr, p[0] + kHeadingLinePixels * std::cos(step.pose.heading),
                p[1] - kHeadingLinePixels * std::sin(step.pose.heading));
  cairo_stroke(cr);
  HullPath(cr, view, step.pose, 2.0 * CybershipModel::kRadius);
  FillAndOutline(cr, colour);
  if (step.collision) {
    SetColour(cr, kCollisionColour);
    cairo_set_line_width(cr, 3.0);
    cairo_arc(cr, p[0], p[1], 16.0, 0, 2 * kPi);
    cairo_stroke(cr);
  }
}

void DrawCaption(cairo_t* cr, const std::string& text) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 13.0);
  SetColour(cr, kOutlineColour);
  cairo_move_to(cr, 8.0, 18.0);
  cairo_show_text(cr, text.c_str());
}

RgbImage PixelsOf(cairo_surface_t* surface, int width, int height) {
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  RgbImage image{width, height, std::vector<std::uint8_t>(3 * width * height)};
  for (int y = 0; y < height; ++y) {
    const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
    for (int x = 0; x < width; ++x) {
      std::uint8_t* out = &image.rgb[3 * (y * width + x)];
      out[0] = (row[x] >> 16) & 255;
      out[1] = (row[x] >> 8) & 255;
      out[2] = row[x] & 255;
    }
  }
  return image;
}

}  // namespace

FrameView FollowView(const Replay& replay, int run, int step, int width, int height) {
  const ReplayRun& followed = replay.runs.at(run);
  const ReplayPose& pose =
      followed.steps[std::min<std::size_t>(step, followed.steps.size() - 1)].pose;
  return {pose.x, pose.y, width / kFollowWidth, width, height};
}

std::array<double, 2> PixelOf(const FrameView& view, double x, double y) {
  return {view.width / 2.0 + (x - view.center_x) * view.scale,
          view.height / 2.0 - (y - view.center_y) * view.scale};
}

RgbImage DrawFrame(const Replay& replay, int step, const FrameView& view, int rays_of_run) {
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, view.width, view.height),
                  &cairo_surface_destroy);
  Context context(cairo_create(surface.get()), &cairo_destroy);
  cairo_t* cr = context.get();
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  SetColour(cr, kBackgroundColour);
  cairo_paint(cr);
  DrawPathAndObstacles(cr, replay.scene, step, view);
  auto last_of = [&](const ReplayRun& run) {
    return std::min(step, static_cast<int>(run.steps.size()) - 1);
  };
  if (rays_of_run >= 0) {
    const ReplayRun& run = replay.runs.at(rays_of_run);
    DrawRays(cr, run.steps[last_of(run)], view);
    DrawLookAheadPoint(cr, run.steps[last_of(run)], view);
  }
  for (std::size_t k = 0; k < replay.runs.size(); ++k) {
    DrawRun(cr, replay.runs[k], last_of(replay.runs[k]), kRunColours[k % kRunColours.size()], view);
  }
  DrawCaption(cr, replay.scene.name + "   step " + std::to_string(step));
  return PixelsOf(surface.get(), view.width, view.height);
}

}  // namespace colav
