#include "eval/study/job_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

#include "eval/study/job_claims.h"
#include "eval/study/process_identity.h"
#include "eval/study/recorded_settings.h"
#include "src/cli.h"
#include "src/error.h"
#include "src/progress.h"

extern char** environ;

namespace colav {
namespace {

enum class JobState { kPending, kRunning, kDone, kFailed };

// Share of its estimate a running job is counted as done at most, until it finishes.
constexpr double kMaxRunningShare = 0.95;
constexpr auto kPollInterval = std::chrono::milliseconds(100);
// How often the shared folder is read for what other ranks did (a local job's end: at once).
constexpr auto kSharedPollInterval = std::chrono::seconds(1);
constexpr int kExecFailedStatus = 127;

std::filesystem::path LogPath(const JobRunnerOptions& options, const StudyJob& job) {
  return options.log_dir / (JobFileStem(job.id) + ".log");
}

// The command line of a job: its program and `args`.
std::vector<std::string> CommandLine(const std::filesystem::path& program_dir, const StudyJob& job,
                                     const std::vector<std::string>& args) {
  std::vector<std::string> command = {(program_dir / job.program).string()};
  command.insert(command.end(), args.begin(), args.end());
  return command;
}

std::vector<char*> ArgumentPointers(std::vector<std::string>& command) {
  std::vector<char*> argv;
  argv.reserve(command.size() + 1);
  for (std::string& arg : command) argv.push_back(arg.data());
  argv.push_back(nullptr);
  return argv;
}

// Runs `command` to its end and returns its exit status with what it wrote to stdout and stderr.
std::pair<int, std::string> RunCapturingOutput(std::vector<std::string> command) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw std::runtime_error("pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  std::vector<char*> argv = ArgumentPointers(command);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  std::string output;
  char buffer[4096];
  for (ssize_t n = read(pipe_ends[0], buffer, sizeof buffer); n > 0;
       n = read(pipe_ends[0], buffer, sizeof buffer)) {
    output.append(buffer, static_cast<std::size_t>(n));
  }
  close(pipe_ends[0]);
  if (spawned != 0) throw UserError(command[0] + ": cannot start (is the project built?)");
  int status = 0;
  waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), output};
}

// Starts the job in its own process group, so that a Ctrl-C at the terminal reaches only the
// runner, which then asks each job once to stop (a second signal would make a trainer abort). The
// program gets SIGTERM when the runner dies (it checkpoints and stops), so that no orphan keeps
// writing into a job that another rank takes over. fork() rather than posix_spawn() for that
// (prctl); the child calls only async-signal-safe functions, and reports a failed exec through a
// close-on-exec pipe.
pid_t Launch(const StudyJob& job, bool resume, const JobRunnerOptions& options) {
  std::vector<std::string> command = CommandLine(
      options.program_dir, job, resume && !job.resume_args.empty() ? job.resume_args : job.args);
  std::vector<char*> argv = ArgumentPointers(command);
  const std::string log = LogPath(options, job).string();
  const pid_t parent = getpid();
  int exec_error[2];
  if (pipe2(exec_error, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(kExecFailedStatus);  // the runner died before prctl
    const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    const int in = open("/dev/null", O_RDONLY);
    if (out >= 0 && in >= 0) {
      dup2(out, STDOUT_FILENO);
      dup2(out, STDERR_FILENO);
      dup2(in, STDIN_FILENO);
      execve(argv[0], argv.data(), environ);
    }
    const int error = errno;
    (void)!write(exec_error[1], &error, sizeof error);
    _exit(kExecFailedStatus);
  }
  close(exec_error[1]);
  int error = 0;
  const ssize_t failed = read(exec_error[0], &error, sizeof error);
  close(exec_error[0]);
  if (failed > 0) {
    waitpid(pid, nullptr, 0);
    throw UserError(command[0] + ": cannot start (is the project built?)");
  }
  return pid;
}

// The model names of an evaluate summary.json, in order (empty when it has none).
std::vector<std::string> EvaluatedModels(const nlohmann::json& summary) {
  std::vector<std::string> names;
  if (!summary.contains("models") || !summary["models"].is_array()) return names;
  for (const nlohmann::json& model : summary["models"]) {
    if (model.contains("name") && model["name"].is_string()) names.push_back(model["name"]);
  }
  return names;
}

// The last non-empty line of `text`.
std::string LastLine(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::string last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

// The contents of a text file ("" when unreadable).
std::string FileText(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The last non-empty line of a job's log, to say why it failed.
std::string LastLogLine(const std::filesystem::path& log) { return LastLine(FileText(log)); }

class Scheduler {
 public:
  Scheduler(const std::vector<StudyJob>& jobs, const JobRunnerOptions& options)
      : jobs_(jobs),
        options_(options),
        states_(jobs.size(), JobState::kPending),
        claims_(options.claim_dir, CurrentProcess(), options.claim_timeout),
        heartbeat_interval_(std::max(std::chrono::seconds(1), options.claim_timeout / 4)) {
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (JobComplete(jobs_[i])) {
        states_[i] = JobState::kDone;
        ++summary_.skipped;
      } else {
        remaining_s_ += jobs_[i].estimated_s;
      }
    }
  }

  JobRunSummary Run() {
    std::filesystem::create_directories(options_.log_dir);
    const StopFlag stop_flag;
    ProgressBar progress("study", static_cast<std::int64_t>(remaining_s_), "work-s");
    auto next_shared_look = std::chrono::steady_clock::now();
    auto next_heartbeat = next_shared_look + heartbeat_interval_;
    while (AnyLeft()) {
      if (StopFlag::StopRequested() && !summary_.stopped) {
        for (const auto& [pid, index] : running_) kill(pid, SIGTERM);
        summary_.stopped = true;
      }
      if (summary_.stopped && running_.empty()) break;
      const auto now = std::chrono::steady_clock::now();
      if (!summary_.stopped && (local_change_ || now >= next_shared_look)) {
        LookAtOtherRanks();
        LaunchReady();
        local_change_ = false;
        next_shared_look = now + kSharedPollInterval;
      }
      if (now >= next_heartbeat) {
        StopJobsTakenOver();
        next_heartbeat = now + heartbeat_interval_;
      }
      Reap();
      progress.Update(static_cast<std::int64_t>(DoneSeconds()),
                      {{"running", std::to_string(running_.size())},
                       {"done", std::to_string(summary_.finished)},
                       {"failed", std::to_string(summary_.failed)}});
      std::this_thread::sleep_for(kPollInterval);
    }
    progress.Finish();
    return summary_;
  }

 private:
  bool AnyLeft() const {
    return std::any_of(states_.begin(), states_.end(), [](JobState s) {
      return s == JobState::kPending || s == JobState::kRunning;
    });
  }

  bool Ready(std::size_t i) const {
    return std::all_of(jobs_[i].dependencies.begin(), jobs_[i].dependencies.end(),
                       [&](std::size_t d) { return states_[d] == JobState::kDone; });
  }

  bool Blocked(std::size_t i) const {
    return std::any_of(jobs_[i].dependencies.begin(), jobs_[i].dependencies.end(),
                       [&](std::size_t d) { return states_[d] == JobState::kFailed; });
  }

  void MarkDoneElsewhere(std::size_t i) {
    states_[i] = JobState::kDone;
    ++summary_.by_others;
    done_s_ += jobs_[i].estimated_s;
    Say("done by another rank: " + jobs_[i].id);
  }

  void MarkFailed(std::size_t i, const std::string& why) {
    states_[i] = JobState::kFailed;
    ++summary_.failed;
    Say(why);
  }

  // Takes in what other ranks did to the jobs not running here: completed or failed them (failures
  // recorded since this run began; older ones are retried).
  void LookAtOtherRanks() {
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (states_[i] != JobState::kPending) continue;
      if (JobComplete(jobs_[i])) {
        MarkDoneElsewhere(i);
      } else if (const auto reason = claims_.FailureSince(jobs_[i].id, session_start_)) {
        MarkFailed(i, "failed " + jobs_[i].id + " on another rank: " + *reason);
      }
    }
  }

  // Ready jobs, longest first, rotated by the rank's start offset.
  std::vector<std::size_t> ReadyJobs() {
    std::vector<std::size_t> ready;
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (states_[i] != JobState::kPending) continue;
      if (Blocked(i)) {
        MarkFailed(i, "skipped " + jobs_[i].id + ": a job it needs failed");
      } else if (Ready(i)) {
        ready.push_back(i);
      }
    }
    std::stable_sort(ready.begin(), ready.end(), [&](std::size_t a, std::size_t b) {
      return jobs_[a].estimated_s > jobs_[b].estimated_s;
    });
    if (!ready.empty()) {
      const auto offset = static_cast<std::size_t>(options_.start_offset) % ready.size();
      std::rotate(ready.begin(), ready.begin() + static_cast<std::ptrdiff_t>(offset), ready.end());
    }
    return ready;
  }

  // Claims and starts ready jobs while fewer than `jobs` run here.
  void LaunchReady() {
    for (const std::size_t i : ReadyJobs()) {
      if (static_cast<int>(running_.size()) >= options_.jobs) break;
      const StudyJob& job = jobs_[i];
      const ClaimAttempt attempt = claims_.TryClaim(job.id, std::chrono::system_clock::now());
      if (!attempt.claimed) {
        if (attempt.previous && waiting_said_.insert(i).second) {
          Say("waiting for " + job.id + ": running on " + HolderName(*attempt.previous));
        }
        continue;
      }
      if (attempt.previous) Say("took over " + job.id + " from " + HolderName(*attempt.previous));
      if (JobComplete(job)) {  // completed between the look and the claim
        claims_.Release(job.id);
        MarkDoneElsewhere(i);
        continue;
      }
      claims_.ClearFailure(job.id);
      Start(i);
    }
  }

  void Start(std::size_t i) {
    const StudyJob& job = jobs_[i];
    const bool resume = !job.resume_marker.empty() && std::filesystem::exists(job.resume_marker);
    const pid_t pid = Launch(job, resume, options_);
    claims_.RecordWorker(job.id, ProcessOnThisHost(pid));
    running_[pid] = i;
    started_[i] = std::chrono::steady_clock::now();
    states_[i] = JobState::kRunning;
    Say((resume ? "resumed " : "started ") + job.id);
  }

  // Refreshes the claims of the running jobs; one that another rank took over (this rank's
  // heartbeat was late) is stopped here, and left to that rank.
  void StopJobsTakenOver() {
    for (const std::string& id : claims_.Heartbeat()) {
      for (const auto& [pid, i] : running_) {
        if (jobs_[i].id != id) continue;
        kill(pid, SIGTERM);
        taken_over_.insert(i);
        Say("lost " + id + " to another rank (its claim was taken over); stopping it here");
      }
    }
  }

  // Whether every job's outputs are complete, whoever ran it.
  bool StudyComplete() const {
    for (std::size_t i = 0; i < jobs_.size(); ++i) {
      if (states_[i] != JobState::kDone && !JobComplete(jobs_[i])) return false;
    }
    return true;
  }

  void Reap() {
    int status = 0;
    for (pid_t pid = waitpid(-1, &status, WNOHANG); pid > 0; pid = waitpid(-1, &status, WNOHANG)) {
      const auto entry = running_.find(pid);
      if (entry == running_.end()) continue;
      const std::size_t i = entry->second;
      running_.erase(entry);
      local_change_ = true;
      const StudyJob& job = jobs_[i];
      // A stop that reached the program as it ended, its outputs complete (mpirun ending a rank
      // just then), leaves a finished job: the next run would only skip it.
      const bool exited_cleanly = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      const bool ok = (exited_cleanly || summary_.stopped) && JobComplete(job);
      if (taken_over_.erase(i) > 0) {
        states_[i] = JobState::kPending;  // the rank that took it over finishes it
      } else if (ok) {
        states_[i] = JobState::kDone;
        ++summary_.finished;
        done_s_ += job.estimated_s;
        Say("finished " + job.id + " in " + FormatDuration(SecondsSince(started_[i])));
        if (StudyComplete()) summary_.completed_study = true;
      } else if (summary_.stopped) {
        states_[i] = JobState::kPending;  // interrupted on request: resumes next time
        Say("stopped " + job.id + " (resumes on the next run)");
      } else {
        const std::string reason =
            LogPath(options_, job).string() + ": " + LastLogLine(LogPath(options_, job));
        claims_.RecordFailure(job.id, reason);
        MarkFailed(i, "failed " + job.id + " (" + reason + ")");
      }
      claims_.Release(job.id);
    }
  }

  double DoneSeconds() const {
    double done = done_s_;
    for (const auto& [pid, i] : running_) {
      done += std::min(SecondsSince(started_.at(i)), kMaxRunningShare * jobs_[i].estimated_s);
    }
    return done;
  }

  static void Say(const std::string& line) { std::fprintf(stderr, "study: %s\n", line.c_str()); }

  const std::vector<StudyJob>& jobs_;
  const JobRunnerOptions& options_;
  std::vector<JobState> states_;
  JobClaims claims_;
  const std::chrono::seconds heartbeat_interval_;
  const WallTime session_start_ = std::chrono::system_clock::now();
  std::map<pid_t, std::size_t> running_;
  std::map<std::size_t, std::chrono::steady_clock::time_point> started_;
  std::set<std::size_t> taken_over_;    // running here, but another rank holds the claim now
  std::set<std::size_t> waiting_said_;  // jobs held elsewhere that the log already named
  bool local_change_ = true;            // a job ended here: look for newly ready jobs at once
  double remaining_s_ = 0.0;
  double done_s_ = 0.0;
  JobRunSummary summary_;
};

}  // namespace

std::map<std::string, std::string> CheckJobConfigurations(
    const std::vector<StudyJob>& jobs, const std::filesystem::path& program_dir) {
  std::map<std::string, std::string> configurations;
  for (const StudyJob& job : jobs) {
    if (!job.check_configuration) continue;
    const std::filesystem::path recorded = job.recorded_settings.empty()
                                               ? job.complete_marker.parent_path() / "config.yaml"
                                               : job.recorded_settings;
    const bool finished = JobComplete(job);
    if (finished && !std::filesystem::exists(recorded)) continue;
    std::vector<std::string> args = job.args;
    args.emplace_back("--print-config");
    const auto [status, output] = RunCapturingOutput(CommandLine(program_dir, job, args));
    if (status != 0) {
      const std::size_t error = output.rfind("error: ");
      const std::string message =
          error == std::string::npos ? LastLine(output) : output.substr(error + 7);
      throw UserError("job " + job.id + ": " + job.program + ": " +
                      message.substr(0, message.find('\n')));
    }
    const std::optional<std::string> difference =
        finished ? FirstSettingDifference(FileText(recorded), output) : std::nullopt;
    if (difference) {
      throw UserError("job " + job.id + ": the finished run in " + recorded.parent_path().string() +
                      " has " + *difference + ": move that folder away to run it again");
    }
    configurations[job.id] = output;
  }
  return configurations;
}

JobRunSummary RunJobs(const std::vector<StudyJob>& jobs, const JobRunnerOptions& options) {
  return Scheduler(jobs, options).Run();
}

bool JobComplete(const StudyJob& job) {
  if (!std::filesystem::exists(job.complete_marker)) return false;
  if (job.complete_marker.extension() != ".json") return true;
  std::ifstream in(job.complete_marker);
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (summary.is_discarded() || !summary.value("finished", true)) return false;
  return job.expected_models.empty() || EvaluatedModels(summary) == job.expected_models;
}

bool AllJobsComplete(const std::vector<StudyJob>& jobs) {
  return std::all_of(jobs.begin(), jobs.end(), JobComplete);
}

std::filesystem::path ProgramFolder() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path();
}

}  // namespace colav
