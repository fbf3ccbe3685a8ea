// Runs commands one at a time, in turns, so that engines raced on a shared machine see the same
// machine: a busy minute falls on all of them rather than on whichever ran then. Each command
// stops itself (SIGSTOP) where its turn ends, as the race runners do with --turn-ms=T; the
// command whose turn it is runs alone, every other one is stopped. Commands start in order, one
// at a time, each until its first stop, so their set-up does not overlap either; then each
// live command in order is continued until it stops again or exits, round after round.
// Turns should be equally long in time, not in work: the kernel's scheduler favours, against
// other load, a process that runs a smaller share of the time, which would be the faster
// engine's if turns were so many steps each.
//
// With --cpu=N first, every command runs on CPU N alone (its affinity set before it starts). On
// a shared machine one core can be slower than another for minutes at a time (its host is busy
// elsewhere); a single-threaded command stopped and continued stays on the core it ran on, so
// without this two commands can spend a whole race on different cores, one slow and one not.
//
// Usage: mink_bench_take_turns [--cpu=N] CMD [ARGS...] [--and CMD [ARGS...]]...
// Output and errors are the commands' own. The exit status is the highest of the commands'
// (a command killed by a signal counts as 128 + the signal), and each non-zero one is named on
// stderr.

#include <sched.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct Command {
  std::vector<char*> argv;  // null-terminated
  pid_t pid = -1;
  bool done = false;
  int status = 0;
};

std::string describe(const Command& command) {
  std::string text;
  for (const char* arg : command.argv) {
    if (arg == nullptr) break;
    if (!text.empty()) text += ' ';
    text += arg;
  }
  return text;
}

// Waits until the command stops or ends; false if it ended.
bool wait_for_stop(Command& command) {
  int status = 0;
  while (waitpid(command.pid, &status, WUNTRACED) < 0) {
    if (errno != EINTR) {
      std::perror("mink_bench_take_turns: waitpid");
      command.done = true;
      command.status = 1;
      return false;
    }
  }
  if (WIFSTOPPED(status)) return true;
  command.done = true;
  command.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return false;
}

// The CPU `digits` names (the N of --cpu=N), when this process may run on it.
std::optional<int> parse_cpu(std::string_view digits) {
  int cpu = -1;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), cpu);
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (error != std::errc() || end != digits.data() + digits.size() || cpu < 0 ||
      cpu >= CPU_SETSIZE || sched_getaffinity(0, sizeof allowed, &allowed) != 0 ||
      !CPU_ISSET(cpu, &allowed)) {
    return std::nullopt;
  }
  return cpu;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<Command> commands(1);
  std::optional<int> cpu;
  int first = 1;
  constexpr std::string_view kCpu = "--cpu=";
  if (argc > 1 && std::string_view(argv[1]).starts_with(kCpu)) {
    cpu = parse_cpu(std::string_view(argv[1]).substr(kCpu.size()));
    if (!cpu) {
      std::fprintf(stderr, "mink_bench_take_turns: %s: not a CPU this process may run on\n",
                   argv[1]);
      return 2;
    }
    first = 2;
  }
  for (int i = first; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--and") {
      commands.emplace_back();
    } else {
      commands.back().argv.push_back(argv[i]);
    }
  }
  for (Command& command : commands) {
    if (command.argv.empty()) {
      std::fprintf(stderr, "usage: %s [--cpu=N] CMD [ARGS...] [--and CMD [ARGS...]]...\n", argv[0]);
      return 2;
    }
    command.argv.push_back(nullptr);
  }

  for (Command& command : commands) {
    std::fflush(stdout);
    command.pid = fork();
    if (command.pid < 0) {
      std::perror("mink_bench_take_turns: fork");
      return 1;
    }
    if (command.pid == 0) {
      if (cpu) {
        cpu_set_t only;
        CPU_ZERO(&only);
        CPU_SET(*cpu, &only);
        if (sched_setaffinity(0, sizeof only, &only) != 0) {
          std::perror("mink_bench_take_turns: sched_setaffinity");
          _exit(127);
        }
      }
      execvp(command.argv[0], command.argv.data());
      std::fprintf(stderr, "mink_bench_take_turns: %s: %s\n", command.argv[0],
                   std::strerror(errno));
      _exit(127);
    }
    wait_for_stop(command);
  }
  for (bool any = true; any;) {
    any = false;
    for (Command& command : commands) {
      if (command.done) continue;
      kill(command.pid, SIGCONT);
      any = wait_for_stop(command) || any;
    }
  }

  int highest = 0;
  for (const Command& command : commands) {
    if (command.status != 0) {
      std::fprintf(stderr, "mink_bench_take_turns: exit status %d: %s\n", command.status,
                   describe(command).c_str());
    }
    highest = std::max(highest, command.status);
  }
  return highest;
}
