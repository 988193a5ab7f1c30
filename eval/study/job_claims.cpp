#include "eval/study/job_claims.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "eval/study/job_graph.h"
#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

constexpr const char* kClaimExtension = ".claim";
constexpr const char* kFailureFile = "failed";
constexpr const char* kReportWrittenFile = "report.written";

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

nlohmann::json ToJson(const ProcessIdentity& process) {
  return {{"host", process.host},
          {"boot_id", process.boot_id},
          {"pid", process.pid},
          {"start_ticks", process.start_ticks}};
}

ProcessIdentity ProcessFromJson(const nlohmann::json& json) {
  return {json.value("host", ""), json.value("boot_id", ""), json.value("pid", std::int64_t{0}),
          json.value("start_ticks", std::uint64_t{0})};
}

std::string ToText(const JobClaim& claim) {
  return nlohmann::json{{"job", claim.job},
                        {"generation", claim.generation},
                        {"holder", ToJson(claim.holder)},
                        {"worker", ToJson(claim.worker)},
                        {"started", claim.started}}
             .dump(2) +
         "\n";
}

std::optional<std::string> ReadText(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The claim in `path`; nullopt when the file is gone. A file that does not parse (damaged by
// hand) counts as a claim of an unknown holder, stale once its heartbeat is old.
std::optional<JobClaim> ReadClaim(const std::filesystem::path& path, const std::string& job) {
  const std::optional<std::string> text = ReadText(path);
  if (!text) return std::nullopt;
  const nlohmann::json json = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  JobClaim claim{job, 0, {}, {}, ""};
  if (json.is_object()) {
    claim.generation = json.value("generation", std::int64_t{0});
    if (json.contains("holder")) claim.holder = ProcessFromJson(json["holder"]);
    if (json.contains("worker")) claim.worker = ProcessFromJson(json["worker"]);
    claim.started = json.value("started", "");
  }
  return claim;
}

// The file's modification time (the heartbeat); nullopt when it is gone.
std::optional<WallTime> ModificationTime(const std::filesystem::path& path) {
  struct stat status {};
  if (stat(path.c_str(), &status) != 0) return std::nullopt;
  return WallTime(std::chrono::duration_cast<WallTime::duration>(
      std::chrono::seconds(status.st_mtim.tv_sec) +
      std::chrono::nanoseconds(status.st_mtim.tv_nsec)));
}

// The generations of the claim files in a job's folder, ascending.
std::vector<std::int64_t> Generations(const std::filesystem::path& job_folder) {
  std::vector<std::int64_t> generations;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(job_folder, error)) {
    if (entry.path().extension() != kClaimExtension) continue;
    const std::string number = entry.path().stem().string();
    if (number.find_first_not_of("0123456789") == std::string::npos && !number.empty()) {
      generations.push_back(std::stoll(number));
    }
  }
  std::sort(generations.begin(), generations.end());
  return generations;
}

std::filesystem::path ClaimPath(const std::filesystem::path& job_folder, std::int64_t generation) {
  return job_folder / (std::to_string(generation) + kClaimExtension);
}

// Creates `path` with `content` unless it exists, never showing it half-written: the content goes
// to a private file first, which link() then gives the name exclusively (atomic on NFS too).
bool CreateExclusively(const std::filesystem::path& path, const std::string& content,
                       const ProcessIdentity& self) {
  const std::filesystem::path draft =
      path.parent_path() /
      ("." + path.filename().string() + "." + self.host + "." + std::to_string(self.pid) + ".tmp");
  {
    std::ofstream out(draft, std::ios::trunc);
    out << content;
    if (!out.flush()) throw UserError(draft.string() + ": cannot write a job claim");
  }
  const int linked = link(draft.c_str(), path.c_str());
  const int link_error = errno;
  std::filesystem::remove(draft);
  if (linked == 0) return true;
  if (link_error == EEXIST) return false;
  throw UserError(path.string() + ": cannot create a job claim (" + std::strerror(link_error) +
                  ")");
}

}  // namespace

std::string HolderName(const JobClaim& claim) {
  return claim.holder.host + ":" + std::to_string(claim.holder.pid);
}

JobClaims::JobClaims(std::filesystem::path folder, ProcessIdentity self,
                     std::chrono::seconds timeout)
    : folder_(std::move(folder)), self_(std::move(self)), timeout_(timeout) {}

std::filesystem::path JobClaims::JobFolder(const std::string& job) const {
  return folder_ / JobFileStem(job);
}

ClaimAttempt JobClaims::TryClaim(const std::string& job, WallTime now) {
  const std::filesystem::path job_folder = JobFolder(job);
  std::filesystem::create_directories(job_folder);
  const std::vector<std::int64_t> generations = Generations(job_folder);
  std::optional<JobClaim> current;
  if (!generations.empty()) {
    const std::filesystem::path path = ClaimPath(job_folder, generations.back());
    const std::optional<WallTime> heartbeat = ModificationTime(path);
    current = ReadClaim(path, job);
    if (!heartbeat || !current) return {};  // released meanwhile: free at the next attempt
    if (!Stale(*current, *heartbeat, now)) return {false, current};
  }
  const JobClaim claim{job, generations.empty() ? 1 : generations.back() + 1, self_, {}, UtcNow()};
  if (!CreateExclusively(ClaimPath(job_folder, claim.generation), ToText(claim), self_)) {
    return {false, std::nullopt};  // another rank was faster
  }
  held_[job] = claim;
  return {true, current};
}

void JobClaims::RecordWorker(const std::string& job, const ProcessIdentity& worker) {
  JobClaim& claim = held_.at(job);
  claim.worker = worker;
  if (StillHeld(claim)) {
    WriteTextFileAtomically(ClaimPath(JobFolder(job), claim.generation), ToText(claim));
  }
}

std::vector<std::string> JobClaims::Heartbeat() {
  std::vector<std::string> lost;
  for (const auto& [job, claim] : held_) {
    if (StillHeld(claim)) {
      utimensat(AT_FDCWD, ClaimPath(JobFolder(job), claim.generation).c_str(), nullptr, 0);
    } else {
      lost.push_back(job);
    }
  }
  for (const std::string& job : lost) held_.erase(job);
  return lost;
}

void JobClaims::Release(const std::string& job) {
  const auto claim = held_.find(job);
  if (claim == held_.end()) return;
  if (StillHeld(claim->second)) {
    // The stale generations first, ours last: until then the job reads as held by us.
    for (const std::int64_t generation : Generations(JobFolder(job))) {
      if (generation <= claim->second.generation) {
        std::filesystem::remove(ClaimPath(JobFolder(job), generation));
      }
    }
  }
  held_.erase(claim);
}

void JobClaims::RecordFailure(const std::string& job, const std::string& reason) {
  const nlohmann::json record = {
      {"job", job}, {"by", ToJson(self_)}, {"reason", reason}, {"time", UtcNow()}};
  WriteTextFileAtomically(JobFolder(job) / kFailureFile, record.dump(2) + "\n");
}

std::optional<std::string> JobClaims::FailureSince(const std::string& job, WallTime since) const {
  const std::filesystem::path path = JobFolder(job) / kFailureFile;
  const std::optional<WallTime> recorded = ModificationTime(path);
  if (!recorded || *recorded < since) return std::nullopt;
  const nlohmann::json record =
      nlohmann::json::parse(ReadText(path).value_or(""), nullptr, /*allow_exceptions=*/false);
  return record.is_object() ? record.value("reason", "") : "";
}

void JobClaims::ClearFailure(const std::string& job) {
  std::filesystem::remove(JobFolder(job) / kFailureFile);
}

bool JobClaims::ClaimReportWriting() {
  std::filesystem::create_directories(folder_);
  const nlohmann::json record = {{"by", ToJson(self_)}, {"time", UtcNow()}};
  return CreateExclusively(folder_ / kReportWrittenFile, record.dump(2) + "\n", self_);
}

void JobClaims::ForgetReportWriting() { std::filesystem::remove(folder_ / kReportWrittenFile); }

bool JobClaims::Stale(const JobClaim& claim, WallTime heartbeat, WallTime now) const {
  if (OnThisHost(claim.holder)) {
    return !StillRunning(claim.holder) && (claim.worker.pid == 0 || !StillRunning(claim.worker));
  }
  return now - heartbeat > timeout_;
}

bool JobClaims::StillHeld(const JobClaim& claim) const {
  const std::filesystem::path job_folder = JobFolder(claim.job);
  const std::vector<std::int64_t> generations = Generations(job_folder);
  if (generations.empty() || generations.back() != claim.generation) return false;
  const std::optional<JobClaim> on_file =
      ReadClaim(ClaimPath(job_folder, claim.generation), claim.job);
  return on_file && on_file->holder == self_;
}

}  // namespace colav
