#include "eval/replay/replay_page.h"

#include <stdexcept>

#include "eval/replay/replay_json.h"
#include "eval/replay/replay_page_template.h"  // generated from replay_page.html
#include "src/atomic_file.h"

namespace colav {
namespace {

constexpr std::string_view kDataMarker = "/*REPLAY_DATA*/";
constexpr std::string_view kDataStart = "<script type=\"application/json\" id=\"replay-data\">";

// JSON that cannot end its <script> element early: "</" becomes the equivalent "<\/".
std::string ScriptSafe(std::string json) {
  for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at + 3)) {
    json.replace(at, 2, "<\\/");
  }
  return json;
}

}  // namespace

std::string ReplayPage(const Replay& replay) {
  std::string html(kReplayPageTemplate);
  const std::size_t marker = html.find(kDataMarker);
  if (marker == std::string::npos) {
    throw std::logic_error("replay page template has no data marker");
  }
  return html.replace(marker, kDataMarker.size(), ScriptSafe(ReplayJson(replay).dump()));
}

Replay ReplayOfPage(const std::string& html) {
  const std::size_t start = html.find(kDataStart);
  const std::size_t end = html.find("</script>", start);
  if (start == std::string::npos || end == std::string::npos) {
    throw std::invalid_argument("not a replay page: no replay-data script");
  }
  const std::size_t begin = start + kDataStart.size();
  const auto document = nlohmann::json::parse(html.substr(begin, end - begin), nullptr, false);
  if (document.is_discarded()) throw std::invalid_argument("replay page: data is not JSON");
  return ReplayFromJson(document);
}

void WriteReplayPage(const Replay& replay, const std::filesystem::path& path) {
  WriteTextFileAtomically(path, ReplayPage(replay));
}

}  // namespace colav
