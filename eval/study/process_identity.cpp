#include "eval/study/process_identity.h"

#include <unistd.h>

#include <fstream>
#include <sstream>

namespace colav {
namespace {

// Fields of /proc/<pid>/stat after the command name (which may hold spaces): the state is the
// first, the start time the 20th.
constexpr int kStartTimeField = 20;

std::string ReadFirstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

struct ProcessStat {
  char state = '?';
  std::uint64_t start_ticks = 0;
};

// The state and start time of /proc/<pid>/stat; start_ticks 0 when there is no such process.
ProcessStat ReadProcessStat(pid_t pid) {
  const std::string line = ReadFirstLine("/proc/" + std::to_string(pid) + "/stat");
  const std::size_t name_end = line.rfind(')');
  if (name_end == std::string::npos) return {};
  std::istringstream fields(line.substr(name_end + 1));
  ProcessStat stat;
  fields >> stat.state;
  std::string skipped;
  for (int field = 2; field < kStartTimeField; ++field) fields >> skipped;
  fields >> stat.start_ticks;
  return stat;
}

std::string HostName() {
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  return name;
}

const std::string& BootId() {
  static const std::string id = ReadFirstLine("/proc/sys/kernel/random/boot_id");
  return id;
}

}  // namespace

ProcessIdentity CurrentProcess() { return ProcessOnThisHost(getpid()); }

ProcessIdentity ProcessOnThisHost(pid_t pid) {
  return {HostName(), BootId(), pid, ReadProcessStat(pid).start_ticks};
}

bool OnThisHost(const ProcessIdentity& process) { return process.boot_id == BootId(); }

bool StillRunning(const ProcessIdentity& process) {
  const ProcessStat stat = ReadProcessStat(static_cast<pid_t>(process.pid));
  return stat.start_ticks != 0 && stat.start_ticks == process.start_ticks && stat.state != 'Z';
}

}  // namespace colav
