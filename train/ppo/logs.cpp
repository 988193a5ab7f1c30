#include "train/ppo/logs.h"

#include <algorithm>
#include <cstdlib>
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

// A field of a log row: a number, written in full (NaN included: explained_variance is NaN for a
// rollout whose returns are all equal).
bool IsNumber(const std::string& field) {
  char* end = nullptr;
  std::strtod(field.c_str(), &end);
  return !field.empty() && end == field.c_str() + field.size();
}

// The fields of row `number` of the log `file`: numbers under `header`, the first an integer
// global step from `previous_step` to `last_step`. A UserError naming the row otherwise.
std::vector<std::string> ParseRow(const std::string& line, const std::string& header,
                                  std::int64_t previous_step, std::int64_t last_step,
                                  const std::string& file, std::size_t number) {
  std::vector<std::string> fields = SplitCsv(line);
  const std::string row = file + ": row " + std::to_string(number);
  if (fields.size() != FieldCount(header) || !std::all_of(fields.begin(), fields.end(), IsNumber)) {
    throw UserError(row + " is not a row of numbers under " + header);
  }
  char* end = nullptr;
  const long long step = std::strtoll(fields[0].c_str(), &end, 10);
  if (*end != '\0' || step < previous_step || step > last_step) {
    throw UserError(row + " has global_step " + fields[0] + " (expected " +
                    std::to_string(previous_step) + " to " + std::to_string(last_step) + ")");
  }
  return fields;
}

// Keeps the header and the first `rows` rows of `path`, which must be complete rows of numbers
// with non-decreasing global steps up to `last_step` (rows after them may be torn: a run killed
// while writing); returns the kept rows.
std::vector<std::vector<std::string>> KeepRows(const std::filesystem::path& path,
                                               const std::string& header, std::int64_t rows,
                                               std::int64_t last_step) {
  const std::string file = path.string();
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line) || line != header) {
    throw UserError(file + ": not a train_ppo log (header expected: " + header + ")");
  }
  std::vector<std::vector<std::string>> kept;
  std::string content = header + "\n";
  std::int64_t previous_step = 0;
  while (static_cast<std::int64_t>(kept.size()) < rows && std::getline(in, line) && !in.eof()) {
    kept.push_back(ParseRow(line, header, previous_step, last_step, file, kept.size() + 1));
    previous_step = std::stoll(kept.back()[0]);
    content.append(line).append("\n");
  }
  if (static_cast<std::int64_t>(kept.size()) < rows) {
    throw UserError(file + " ends after " + std::to_string(kept.size()) +
                    " complete rows; the checkpoint continues from row " + std::to_string(rows));
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
                           std::optional<KeptLogRows> resume) {
  const std::filesystem::path episodes = run_dir / "episodes.csv";
  const std::filesystem::path updates = run_dir / "updates.csv";
  if (resume) {
    for (const auto& row :
         KeepRows(episodes, kEpisodesHeader, resume->episodes, resume->last_step)) {
      Remember({std::stod(row[3]), std::stod(row[4]), std::stod(row[5]), std::stod(row[6]),
                row[7] == "1", row[8] == "1"});
    }
    KeepRows(updates, kUpdatesHeader, resume->updates, resume->last_step);
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
