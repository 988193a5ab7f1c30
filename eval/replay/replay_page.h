// The replay page: one self-contained HTML file (inline script and data, no network) that
// animates a replay on a canvas (eval/replay/replay_page.html documents its view and controls).
#pragma once

#include <filesystem>
#include <string>

#include "eval/replay/replay.h"

namespace colav {

/// The page's HTML with the replay embedded.
std::string ReplayPage(const Replay& replay);

/// The replay a page embeds; std::invalid_argument when the text is not a replay page.
Replay ReplayOfPage(const std::string& html);

/// Writes the page to `path` atomically.
void WriteReplayPage(const Replay& replay, const std::filesystem::path& path);

}  // namespace colav
