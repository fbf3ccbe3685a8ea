// `mink sweep`: parameter sweeps run by the Python module minkowski on a Dask cluster. The
// command hands its arguments to `python3 -m minkowski sweep`, which parses them (so `mink
// sweep --help` is Python's help), and exits with its exit code.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "exit_codes.hpp"

extern char** environ;

namespace mink::cli {

namespace {

// Imports the module with a clear message (and exit code 4) when it is missing, then runs the
// sweep command with the arguments after "--".
constexpr const char* kBootstrap =
    "import sys\n"
    "try:\n"
    "    import minkowski.__main__ as command\n"
    "except ImportError as error:\n"
    "    sys.stderr.write('mink sweep: needs the Python module minkowski for ' + sys.executable +\n"
    "        ' (' + str(error) + '): build it with make python, then set PYTHONPATH=BUILD/python "
    "'\n"
    "        'or pip install .\\n')\n"
    "    sys.exit(4)\n"
    "sys.exit(command.main(['sweep'] + sys.argv[1:], prog='mink'))\n";

std::string python_program() {
  if (const char* chosen = std::getenv("MINK_PYTHON"); chosen != nullptr && *chosen != '\0') {
    return chosen;
  }
  return MINK_PYTHON_EXECUTABLE;
}

// The package built beside this program (BUILD/bin/mink, BUILD/python/minkowski), if any.
std::string build_tree_package_dir() {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return {};
  const std::filesystem::path dir = self.parent_path().parent_path() / "python";
  return std::filesystem::exists(dir / "minkowski" / "__init__.py", error) ? dir.string()
                                                                           : std::string();
}

int run_python_sweep(const std::vector<std::string>& arguments, Streams streams) {
  const std::string python = python_program();
  std::vector<std::string> argv_strings = {python, "-c", kBootstrap};
  argv_strings.insert(argv_strings.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& s : argv_strings) argv.push_back(s.data());
  argv.push_back(nullptr);

  // The environment, with the build tree's package first on PYTHONPATH.
  std::vector<std::string> environment;
  const std::string package_dir = build_tree_package_dir();
  bool path_set = false;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    std::string variable = *entry;
    if (!package_dir.empty() && variable.rfind("PYTHONPATH=", 0) == 0) {
      const std::string rest = variable.substr(std::strlen("PYTHONPATH="));
      variable = "PYTHONPATH=" + package_dir + (rest.empty() ? "" : ":" + rest);
      path_set = true;
    }
    environment.push_back(std::move(variable));
  }
  if (!package_dir.empty() && !path_set) environment.push_back("PYTHONPATH=" + package_dir);
  std::vector<char*> envp;
  for (std::string& s : environment) envp.push_back(s.data());
  envp.push_back(nullptr);

  streams.out.flush();
  streams.err.flush();
  pid_t pid = 0;
  const int spawned =
      posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), envp.data());
  if (spawned != 0) {
    streams.err << "mink: sweep needs Python 3 with the module minkowski: cannot run '" << python
                << "' (" << std::strerror(spawned)
                << "); install python3 or set MINK_PYTHON to the interpreter\n";
    return kRuntimeFailure;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      streams.err << "mink: sweep: lost the Python process (" << std::strerror(errno) << ")\n";
      return kRuntimeFailure;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  streams.err << "mink: sweep: the Python process was killed by signal " << WTERMSIG(status)
              << '\n';
  return kRuntimeFailure;
}

}  // namespace

Action add_sweep_command(CLI::App& app, Streams streams) {
  CLI::App* command = app.add_subcommand(
      "sweep",
      "Run every variant of a scene on a Dask cluster (Python module minkowski): mink sweep "
      "SCENE --vary KEY=a:b:n ... [--workers N] [--out FILE.csv]; 'mink sweep --help' for all "
      "options. Exit 4 when Python or the module is missing.");
  // Every argument, --help included, goes to Python unparsed.
  command->prefix_command();
  command->allow_extras();
  command->set_help_flag();
  return [command, streams] { return run_python_sweep(command->remaining(), streams); };
}

}  // namespace mink::cli
