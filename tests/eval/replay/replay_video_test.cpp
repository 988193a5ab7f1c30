// GIF frames of a replay, decoded with giflib: one per frame step, the vessel drawn where it was.
#include "eval/replay/replay_video.h"

#include <gif_lib.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "eval/replay/scene_frame.h"
#include "tests/eval/replay/replay_episode.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

struct DecodedGif {
  int width = 0;
  int height = 0;
  std::vector<RgbImage> frames;
};

DecodedGif ReadGif(const std::filesystem::path& path) {
  int error = 0;
  GifFileType* file = DGifOpenFileName(path.c_str(), &error);
  EXPECT_NE(file, nullptr) << GifErrorString(error);
  DecodedGif gif;
  if (file == nullptr) return gif;
  EXPECT_EQ(DGifSlurp(file), GIF_OK);
  gif.width = file->SWidth;
  gif.height = file->SHeight;
  for (int f = 0; f < file->ImageCount; ++f) {
    const SavedImage& image = file->SavedImages[f];
    const ColorMapObject* map =
        image.ImageDesc.ColorMap != nullptr ? image.ImageDesc.ColorMap : file->SColorMap;
    RgbImage frame{image.ImageDesc.Width, image.ImageDesc.Height, {}};
    for (int i = 0; i < frame.width * frame.height; ++i) {
      const GifColorType& c = map->Colors[image.RasterBits[i]];
      frame.rgb.insert(frame.rgb.end(), {c.Red, c.Green, c.Blue});
    }
    gif.frames.push_back(std::move(frame));
  }
  DGifCloseFile(file, &error);
  return gif;
}

// Pixels of exactly this colour within `radius` pixels of (x, y).
int PixelsOfColour(const RgbImage& image, std::array<double, 2> at, int radius, FrameColour c) {
  int count = 0;
  for (int y = static_cast<int>(at[1]) - radius; y <= static_cast<int>(at[1]) + radius; ++y) {
    for (int x = static_cast<int>(at[0]) - radius; x <= static_cast<int>(at[0]) + radius; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const std::uint8_t* p = &image.rgb[3 * (y * image.width + x)];
      count += p[0] == c.r && p[1] == c.g && p[2] == c.b;
    }
  }
  return count;
}

TEST(FrameSteps, EveryStrideStepAndTheLast) {
  EXPECT_EQ(FrameSteps(10, 3), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(FrameSteps(11, 3), (std::vector<int>{0, 3, 6, 9, 10}));
  EXPECT_EQ(FrameSteps(1, 5), (std::vector<int>{0}));
  EXPECT_THROW(FrameSteps(10, 0), std::invalid_argument);
}

TEST(ReplayGif, FramesShowTheVesselAndTheObstacleWhereTheyWere) {
  const Replay replay = testing_util::HeadOnEpisode().replay;
  testing_util::TemporaryFolder folder;
  const int stride = 25;
  WriteReplayGif(replay, folder / "episode.gif", stride);
  const DecodedGif gif = ReadGif(folder / "episode.gif");
  const std::vector<int> steps = FrameSteps(ReplayLength(replay), stride);
  ASSERT_EQ(gif.frames.size(), steps.size());
  EXPECT_EQ(gif.width, kVideoFrameSize);
  EXPECT_EQ(gif.height, kVideoFrameSize);
  for (std::size_t f = 0; f < steps.size(); ++f) {
    const FrameView view = FollowView(replay, 0, steps[f], kVideoFrameSize, kVideoFrameSize);
    const ReplayPose& vessel = replay.runs[0].steps[steps[f]].pose;
    EXPECT_GT(PixelsOfColour(gif.frames[f], PixelOf(view, vessel.x, vessel.y), 3, kRunColours[0]),
              8)
        << "frame " << f;
    const ReplayPose& obstacle = replay.scene.vessel_poses[steps[f]][0];
    const auto obstacle_pixel = PixelOf(view, obstacle.x, obstacle.y);
    if (obstacle_pixel[0] > 5 && obstacle_pixel[1] > 5 && obstacle_pixel[1] < kVideoFrameSize - 5) {
      EXPECT_GT(PixelsOfColour(gif.frames[f], obstacle_pixel, 3, kObstacleColour), 8)
          << "frame " << f;
    }
  }
  // The last frame is the collision: the obstacle is in view, next to the vessel, ringed.
  const FrameView last_view = FollowView(replay, 0, steps.back(), kVideoFrameSize, kVideoFrameSize);
  const ReplayPose& obstacle = replay.scene.vessel_poses[steps.back()][0];
  EXPECT_GT(PixelsOfColour(gif.frames.back(), PixelOf(last_view, obstacle.x, obstacle.y), 3,
                           kObstacleColour),
            8);
  EXPECT_GT(PixelsOfColour(gif.frames.back(), {240.0, 240.0}, 20, kCollisionColour), 20);
}

TEST(ReplayGif, SameReplaySameBytes) {
  const Replay replay = testing_util::HeadOnEpisode().replay;
  testing_util::TemporaryFolder folder;
  WriteReplayGif(replay, folder / "a.gif", 100);
  WriteReplayGif(replay, folder / "b.gif", 100);
  EXPECT_EQ(testing_util::ReadFile(folder / "a.gif"), testing_util::ReadFile(folder / "b.gif"));
}

// PATH set to `folder` for the lifetime of the object.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& path) {
    const char* saved = std::getenv("PATH");
    saved_ = saved == nullptr ? "" : saved;
    setenv("PATH", path.c_str(), 1);
  }
  ~ScopedPath() { setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

// A stand-in ffmpeg that records its arguments and stores the raw frames it is sent as the
// output file: the frames piped are whole 480x480 RGB images, one per frame step.
TEST(ReplayMp4, PipesOneRawFramePerFrameStepToFfmpeg) {
  testing_util::TemporaryFolder folder;
  testing_util::WriteFile(folder / "ffmpeg",
                          "#!/bin/sh\necho \"$@\" > \"${0%/*}/arguments\"\n"
                          "for last; do :; done\nexec /bin/cat > \"$last\"\n");
  std::filesystem::permissions(folder / "ffmpeg", std::filesystem::perms::owner_all);
  const Replay replay = testing_util::HeadOnEpisode().replay;
  {
    const ScopedPath path(folder.path().string());
    WriteReplayMp4(replay, folder / "episode.mp4", 50);
  }
  const std::size_t frames = FrameSteps(ReplayLength(replay), 50).size();
  EXPECT_EQ(std::filesystem::file_size(folder / "episode.mp4"),
            frames * kVideoFrameSize * kVideoFrameSize * 3);
  const std::string arguments = testing_util::ReadFile(folder / "arguments");
  EXPECT_NE(arguments.find("-f rawvideo -pix_fmt rgb24 -s 480x480 -framerate 10 -i -"),
            std::string::npos)
      << arguments;
}

TEST(ReplayMp4, MissingFfmpegIsAUserErrorNamingTheFlag) {
  const ScopedPath path("/nonexistent");
  try {
    RequireFfmpeg("--mp4");
    ADD_FAILURE() << "no error without ffmpeg";
  } catch (const UserError& error) {
    EXPECT_NE(std::string(error.what()).find("--mp4: ffmpeg is not on PATH"), std::string::npos);
  }
}

}  // namespace
}  // namespace colav
