#include "eval/study/job_claims.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <thread>

#include "tests/src/test_util.h"

namespace colav {
namespace {

using std::chrono::seconds;
using testing_util::TemporaryFolder;

constexpr seconds kTimeout(60);

// A rank on another machine: its claims are judged by their heartbeat only.
ProcessIdentity OtherHost(int n) {
  return {"node" + std::to_string(n), "boot-of-node" + std::to_string(n), 1000 + n, 1};
}

// A process of this host that has ended (pid and start time recorded while it ran).
ProcessIdentity DeadProcess() {
  const pid_t pid = fork();
  if (pid == 0) {
    pause();
    _exit(0);
  }
  const ProcessIdentity identity = ProcessOnThisHost(pid);
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  return identity;
}

// A sleeping process of this host, killed with the object.
class LiveProcess {
 public:
  LiveProcess() : pid_(fork()) {
    if (pid_ == 0) {
      pause();
      _exit(0);
    }
  }
  ~LiveProcess() { Kill(); }
  ProcessIdentity Identity() const { return ProcessOnThisHost(pid_); }
  void Kill() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }

 private:
  pid_t pid_;
};

WallTime Now() { return std::chrono::system_clock::now(); }

TEST(JobClaimsTest, AJobIsHeldByOneRankUntilReleased) {
  const TemporaryFolder folder;
  JobClaims mine(folder.path(), CurrentProcess(), kTimeout);
  JobClaims other(folder.path(), OtherHost(1), kTimeout);
  EXPECT_TRUE(mine.TryClaim("ppo/a/seed_0", Now()).claimed);
  const ClaimAttempt refused = other.TryClaim("ppo/a/seed_0", Now());
  EXPECT_FALSE(refused.claimed);
  ASSERT_TRUE(refused.previous);
  EXPECT_EQ(refused.previous->holder, CurrentProcess());
  EXPECT_TRUE(other.TryClaim("ppo/a/seed_1", Now()).claimed);  // other jobs stay free
  EXPECT_FALSE(mine.TryClaim("ppo/a/seed_1", Now()).claimed);

  mine.Release("ppo/a/seed_0");
  const ClaimAttempt after_release = other.TryClaim("ppo/a/seed_0", Now());
  EXPECT_TRUE(after_release.claimed);
  EXPECT_FALSE(after_release.previous);  // a fresh claim, not a takeover
  EXPECT_TRUE(mine.Heartbeat().empty());
}

TEST(JobClaimsTest, TheClaimOfADeadProcessOnThisHostIsTakenOverAtOnce) {
  const TemporaryFolder folder;
  JobClaims dead(folder.path(), DeadProcess(), kTimeout);
  ASSERT_TRUE(dead.TryClaim("vae/shallow", Now()).claimed);
  JobClaims mine(folder.path(), CurrentProcess(), kTimeout);
  const ClaimAttempt takeover = mine.TryClaim("vae/shallow", Now());  // no timeout to wait for
  EXPECT_TRUE(takeover.claimed);
  ASSERT_TRUE(takeover.previous);
  EXPECT_EQ(takeover.previous->generation, 1);
  // The old holder, were it still around, finds its claim gone and must stop; its release
  // leaves the new claim alone.
  EXPECT_EQ(dead.Heartbeat(), std::vector<std::string>{"vae/shallow"});
  dead.Release("vae/shallow");
  EXPECT_FALSE(
      JobClaims(folder.path(), OtherHost(1), kTimeout).TryClaim("vae/shallow", Now()).claimed);
  EXPECT_TRUE(mine.Heartbeat().empty());
}

TEST(JobClaimsTest, AClaimLivesWhileTheProgramItStartedRuns) {
  const TemporaryFolder folder;
  LiveProcess worker;
  JobClaims dead(folder.path(), DeadProcess(), kTimeout);
  ASSERT_TRUE(dead.TryClaim("ppo/b/seed_0", Now()).claimed);
  dead.RecordWorker("ppo/b/seed_0", worker.Identity());
  JobClaims mine(folder.path(), CurrentProcess(), kTimeout);
  // Its rank died, but the program (which got SIGTERM) still writes its checkpoint.
  EXPECT_FALSE(mine.TryClaim("ppo/b/seed_0", Now()).claimed);
  worker.Kill();
  EXPECT_TRUE(mine.TryClaim("ppo/b/seed_0", Now()).claimed);
}

TEST(JobClaimsTest, AClaimOfAnotherHostIsStaleWhenItsHeartbeatIsOlderThanTheTimeout) {
  const TemporaryFolder folder;
  JobClaims remote(folder.path(), OtherHost(1), kTimeout);
  JobClaims mine(folder.path(), CurrentProcess(), kTimeout);
  ASSERT_TRUE(remote.TryClaim("eval/study", Now()).claimed);
  EXPECT_FALSE(mine.TryClaim("eval/study", Now() + kTimeout / 2).claimed);
  EXPECT_TRUE(remote.Heartbeat().empty());
  EXPECT_FALSE(mine.TryClaim("eval/study", Now() + kTimeout - seconds(5)).claimed);
  const ClaimAttempt takeover = mine.TryClaim("eval/study", Now() + kTimeout + seconds(5));
  EXPECT_TRUE(takeover.claimed);
  ASSERT_TRUE(takeover.previous);
  EXPECT_EQ(HolderName(*takeover.previous), "node1:1001");
  // The remote rank was only late: its next heartbeat tells it that it lost the job.
  EXPECT_EQ(remote.Heartbeat(), std::vector<std::string>{"eval/study"});
}

// Threads that wait for each other before every step, so that they claim each job at once.
class StepBarrier {
 public:
  explicit StepBarrier(int threads) : threads_(threads) {}
  void Wait() {
    const int step = step_;
    if (++arrived_ == threads_) {
      arrived_ = 0;
      ++step_;
    } else {
      while (step_ == step) std::this_thread::yield();
    }
  }

 private:
  const int threads_;
  std::atomic<int> arrived_{0};
  std::atomic<int> step_{0};
};

TEST(JobClaimsTest, OfManyRanksClaimingAtOnceExactlyOneGetsEachJob) {
  const TemporaryFolder folder;
  constexpr int kRanks = 8;
  constexpr int kJobs = 200;
  // Half the jobs start with a stale claim (a dead holder), so takeovers race too.
  const ProcessIdentity dead_holder = DeadProcess();
  for (int j = 0; j < kJobs; j += 2) {
    JobClaims dead(folder.path(), dead_holder, kTimeout);
    ASSERT_TRUE(dead.TryClaim("job/" + std::to_string(j), Now()).claimed);
  }
  std::vector<std::atomic<int>> claims(kJobs);
  StepBarrier barrier(kRanks);
  std::vector<std::thread> ranks;
  for (int r = 0; r < kRanks; ++r) {
    ranks.emplace_back([&, r] {
      JobClaims rank(folder.path(), OtherHost(r), kTimeout);
      for (int j = 0; j < kJobs; ++j) {
        barrier.Wait();
        if (rank.TryClaim("job/" + std::to_string(j), Now()).claimed) ++claims[j];
      }
    });
  }
  for (std::thread& rank : ranks) rank.join();
  for (int j = 0; j < kJobs; ++j) EXPECT_EQ(claims[j], 1) << "job/" << j;
}

TEST(JobClaimsTest, FailuresAreSeenByTheRanksRunningAtTheTime) {
  const TemporaryFolder folder;
  JobClaims remote(folder.path(), OtherHost(1), kTimeout);
  JobClaims mine(folder.path(), CurrentProcess(), kTimeout);
  const WallTime before = Now() - seconds(1);
  ASSERT_TRUE(remote.TryClaim("data", Now()).claimed);
  remote.RecordFailure("data", "logs/data.log: error: disk full");
  remote.Release("data");
  EXPECT_EQ(mine.FailureSince("data", before), "logs/data.log: error: disk full");
  EXPECT_FALSE(mine.FailureSince("data", Now() + seconds(10)));  // a later run retries it
  EXPECT_FALSE(mine.FailureSince("vae/x", before));
  mine.ClearFailure("data");
  EXPECT_FALSE(mine.FailureSince("data", before));
}

TEST(JobClaimsTest, OneRankWritesTheReportOfACompletion) {
  const TemporaryFolder folder;
  JobClaims first(folder / "claims", OtherHost(1), kTimeout);
  JobClaims second(folder / "claims", OtherHost(2), kTimeout);
  EXPECT_TRUE(first.ClaimReportWriting());
  EXPECT_FALSE(second.ClaimReportWriting());
  EXPECT_FALSE(first.ClaimReportWriting());
  second.ForgetReportWriting();  // the study grew: its next completion needs a report
  EXPECT_TRUE(second.ClaimReportWriting());
}

}  // namespace
}  // namespace colav
