#include "train/ppo/logs.h"

#include <sstream>
#include <string>
#include <vector>

#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr std::size_t kRollingEpisodes = 100;

constexpr char kEpisodesHeader[] =
    "global_step,env,seed,reward,progress,mean_cte,steps,collision,goal,truncated";
constexpr char kUpdatesHeader[] =
    "global_step,n_updates,policy_gradient_loss,value_loss,entropy_loss,approx_kl,clip_fraction,"
    "loss,explained_variance,std,fps,rollout_s,update_s";

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}

std::size_t FieldCount(const std::string& header) { return SplitCsv(header).size(); }

// Keeps the header and the complete rows of `path` whose global_step is at most `step`; returns
// the kept rows.
std::vector<std::vector<std::string>> TruncateAfter(const std::filesystem::path& path,
                                                    const std::string& header, std::int64_t step) {
  std::vector<std::vector<std::string>> kept;
  std::ifstream in(path);
  std::string line;
  std::string content = header + "\n";
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> fields = SplitCsv(line);
    if (fields.size() != FieldCount(header) || in.eof()) break;  // a torn last line
    if (std::stoll(fields[0]) > step) break;
    content += line + "\n";
    kept.push_back(std::move(fields));
  }
  WriteTextFileAtomically(path, content);
  return kept;
}

std::ofstream OpenForAppend(const std::filesystem::path& path, const std::string& header) {
  const bool fresh = !std::filesystem::exists(path) || std::filesystem::file_size(path) == 0;
  std::ofstream out(path, std::ios::app);
  if (!out) throw UserError("cannot write '" + path.string() + "'");
  if (fresh) out << header << '\n';
  out.precision(9);
  return out;
}

}  // namespace

TrainingLogs::TrainingLogs(const std::filesystem::path& run_dir,
                           std::optional<std::int64_t> resume_step) {
  const std::filesystem::path episodes = run_dir / "episodes.csv";
  const std::filesystem::path updates = run_dir / "updates.csv";
  if (resume_step) {
    if (std::filesystem::exists(episodes)) {
      for (const auto& row : TruncateAfter(episodes, kEpisodesHeader, *resume_step)) {
        Remember({std::stod(row[3]), std::stod(row[4]), std::stod(row[5]), std::stod(row[6]),
                  row[7] == "1", row[8] == "1"});
      }
    }
    if (std::filesystem::exists(updates)) TruncateAfter(updates, kUpdatesHeader, *resume_step);
  } else {
    std::filesystem::remove(episodes);
    std::filesystem::remove(updates);
  }
  episodes_ = OpenForAppend(episodes, kEpisodesHeader);
  updates_ = OpenForAppend(updates, kUpdatesHeader);
}

void TrainingLogs::AddEpisode(std::int64_t global_step, const FinishedEpisode& episode) {
  const EpisodeMetrics& m = episode.metrics;
  episodes_ << global_step << ',' << episode.env << ',' << episode.seed << ','
            << m.cumulative_reward << ',' << m.progress << ',' << m.mean_abs_cte << ',' << m.steps
            << ',' << m.collision << ',' << m.goal_reached << ',' << m.truncated << '\n';
  Remember({m.cumulative_reward, m.progress, m.mean_abs_cte, static_cast<double>(m.steps),
            m.collision, m.goal_reached});
}

void TrainingLogs::AddUpdate(std::int64_t global_step, const UpdateStats& stats,
                             const IterationTiming& timing) {
  updates_ << global_step << ',' << stats.n_updates << ',' << stats.policy_gradient_loss << ','
           << stats.value_loss << ',' << stats.entropy_loss << ',' << stats.approx_kl << ','
           << stats.clip_fraction << ',' << stats.loss << ',' << stats.explained_variance << ','
           << stats.std << ',' << timing.fps << ',' << timing.rollout_s << ',' << timing.update_s
           << '\n';
}

void TrainingLogs::Flush() {
  episodes_.flush();
  updates_.flush();
}

void TrainingLogs::Remember(const EpisodeSummary& episode) {
  window_.push_back(episode);
  if (window_.size() > kRollingEpisodes) window_.pop_front();
}

RollingEpisodeStats TrainingLogs::Rolling() const {
  RollingEpisodeStats stats;
  stats.count = static_cast<int>(window_.size());
  if (window_.empty()) return stats;
  for (const EpisodeSummary& e : window_) {
    stats.reward += e.reward;
    stats.progress += e.progress;
    stats.mean_cte += e.mean_cte;
    stats.steps += e.steps;
    stats.collision_rate += e.collision;
    stats.goal_rate += e.goal;
  }
  const double n = stats.count;
  stats.reward /= n;
  stats.progress /= n;
  stats.mean_cte /= n;
  stats.steps /= n;
  stats.collision_rate /= n;
  stats.goal_rate /= n;
  return stats;
}

}  // namespace colav
