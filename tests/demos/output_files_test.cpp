// Outputs survive interruption: every file `mink` writes goes to a temporary name and is renamed
// when complete, so a run killed at any moment leaves either the earlier file or the new one.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_support.hpp"
#include "exit_codes.hpp"
#include "mink/engine/scene_file.hpp"
#include "mink/error.hpp"
#include "mink/output_file.hpp"

namespace {

namespace fs = std::filesystem;
using namespace mink_test;

// Starts `mink ARGS` with its output thrown away; returns its process id.
pid_t start_mink(const std::vector<std::string>& args) {
  std::vector<std::string> full = {MINK_BINARY};
  full.insert(full.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : full) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

int wait_exit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A temporary file OutputFile makes for `name`: hidden, ".NAME.XXXXXX.partial.EXT".
bool is_temporary_of(const std::string& entry, const std::string& name) {
  const std::string extension = fs::path(name).extension().string();
  return entry.rfind("." + name + ".", 0) == 0 &&
         entry.size() == name.size() + 2 + 6 + 8 + extension.size() &&
         entry.find(".partial" + extension, name.size() + 8) != std::string::npos;
}

// The case: `mink run many_pyramids --steps 3 --save FILE` killed (SIGKILL) at 40
// seeded moments spread over the run's measured length, with an earlier complete FILE in
// place. Every time, FILE is byte for byte either the earlier file or the complete new one,
// and loads; nothing else is left but the hidden temporary file of a killed run.
TEST(OutputFiles, SaveKilledAtRandomMomentsLeavesTheOldOrTheNewFile) {
  const fs::path dir = fresh_dir("killed_save");
  const fs::path file = dir / "state.json";
  const fs::path reference = dir / "reference.json";
  ASSERT_EQ(
      run_cli({"run", "pyramid", "--steps", "1", "--no-render", "--save", file.string()}).code, 0);
  const std::string earlier = read_text(file);
  // Both candidates load, so a file equal to either byte for byte does too.
  ASSERT_NO_THROW(mink::load_scene_file(file));
  const std::vector<std::string> args = {"run", "many_pyramids", "--steps",
                                         "3",   "--no-render",   "--save"};
  auto with_save = [&](const fs::path& path) {
    std::vector<std::string> a = args;
    a.push_back(path.string());
    return a;
  };
  const auto started = std::chrono::steady_clock::now();
  ASSERT_EQ(wait_exit(start_mink(with_save(reference))), 0);
  const double run_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::string complete = read_text(reference);
  ASSERT_NE(complete, earlier);
  ASSERT_NO_THROW(mink::load_scene_file(reference));

  std::mt19937_64 random(19);
  std::uniform_real_distribution<double> jitter(0, 1);
#ifdef MINK_SANITIZED_BUILD
  constexpr int kKills = 12;  // each run takes several times longer under the sanitizers
#else
  constexpr int kKills = 40;
#endif
  int found_earlier = 0;
  int found_new = 0;
  for (int kill = 0; kill < kKills; ++kill) {
    // Moments from the start to a little past the measured end, one in each 40th.
    const double at = 1.1 * run_seconds * (kill + jitter(random)) / kKills;
    const pid_t pid = start_mink(with_save(file));
    std::this_thread::sleep_for(std::chrono::duration<double>(at));
    ::kill(pid, SIGKILL);
    wait_exit(pid);
    const std::string now = read_text(file);
    ASSERT_TRUE(now == earlier || now == complete)
        << "kill " << kill << " at " << at << " s left " << now.size() << " bytes";
    (now == earlier ? found_earlier : found_new) += 1;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      // The solver state beside each scene file (FILE.state, written first) carries a hash of
      // the JSON it belongs to, so a state file newer than its scene is found out and ignored.
      if (name == "state.json" || name == "reference.json" || name == "state.json.state" ||
          name == "reference.json.state") {
        continue;
      }
      ASSERT_TRUE(is_temporary_of(name, "state.json") || is_temporary_of(name, "state.json.state"))
          << "left behind: " << name;
      fs::remove(entry.path());
    }
    // The next kill starts from the earlier file again.
    write_text(file, earlier);
  }
  std::cout << "run of " << run_seconds << " s killed " << kKills << " times: " << found_earlier
            << " left the earlier file, " << found_new << " the new one\n";
}

// A full disk (/dev/full takes nothing) while the run writes its statistics is exit 5 naming
// the file and the reason; the scene file saved by an earlier run is untouched and no
// temporary file is left.
TEST(OutputFiles, FullDiskIsExit5AndLeavesEarlierFiles) {
  const fs::path dir = fresh_dir("full_disk");
  const fs::path saved = dir / "end.json";
  ASSERT_EQ(
      run_cli({"run", "pyramid", "--steps", "1", "--no-render", "--save", saved.string()}).code, 0);
  const std::string earlier = read_text(saved);
  const std::string earlier_state = read_text(saved.string() + ".state");
  const CliResult r = run_cli({"run", "pyramid", "--steps", "200", "--no-render", "--stats",
                               "/dev/full", "--save", saved.string()});
  EXPECT_EQ(r.code, mink::cli::kOutputFailure) << r.err;
  EXPECT_NE(r.err.find("mink: cannot write --stats file '/dev/full': No space left on device"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read_text(saved), earlier);
  EXPECT_EQ(read_text(saved.string() + ".state"), earlier_state);
  std::vector<std::string> entries;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    entries.push_back(entry.path().filename().string());
  }
  std::sort(entries.begin(), entries.end());
  EXPECT_EQ(entries, (std::vector<std::string>{"end.json", "end.json.state"}));
}

// A file that cannot be completed is never renamed over the earlier one, and its temporary
// file goes; a committed file holds exactly what was written.
TEST(OutputFiles, OnlyACommittedFileReplacesTheEarlierOne) {
  const fs::path dir = fresh_dir("output_file");
  const fs::path path = dir / "out.csv";
  write_text(path, "earlier\n");
  {
    mink::OutputFile file(path, "test file");
    file.stream() << "half of it";
    EXPECT_EQ(read_text(path), "earlier\n");
    EXPECT_TRUE(fs::exists(file.writing_path()));
    EXPECT_TRUE(is_temporary_of(file.writing_path().filename().string(), "out.csv"));
  }  // dropped without commit(): an error part-way
  EXPECT_EQ(read_text(path), "earlier\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  mink::OutputFile file(path, "test file");
  file.stream() << "complete\n";
  file.commit();
  EXPECT_TRUE(file.committed());
  EXPECT_EQ(read_text(path), "complete\n");
  EXPECT_FALSE(fs::exists(file.writing_path()));
  // A new file gets the mode the umask gives any new file; a replaced one keeps its own.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  const fs::path fresh = dir / "fresh.csv";
  mink::OutputFile made(fresh, "test file");
  made.commit();
  EXPECT_EQ(fs::status(fresh).permissions(), static_cast<fs::perms>(0666 & ~mask));
  fs::permissions(path, static_cast<fs::perms>(0640));
  mink::OutputFile again(path, "test file");
  again.stream() << "again\n";
  again.commit();
  EXPECT_EQ(fs::status(path).permissions(), static_cast<fs::perms>(0640));
  EXPECT_EQ(read_text(path), "again\n");
  // In place for what is not a regular file: /dev/full refuses the bytes at commit.
  mink::OutputFile full("/dev/full", "test file");
  full.stream() << std::string(1 << 16, 'x');
  try {
    full.commit();
    ADD_FAILURE() << "writing /dev/full succeeded";
  } catch (const mink::FileWriteError& error) {
    EXPECT_NE(std::string(error.what()).find("No space left on device"), std::string::npos)
        << error.what();
  }
}

// An unwritable place (under a regular file, or a directory where the file should be) is
// exit 5 naming the path, for every kind of output.
TEST(OutputFiles, UnwritablePathsAreExit5) {
  const fs::path dir = fresh_dir("unwritable_paths");
  const fs::path plain = dir / "plain";
  write_text(plain, "a file\n");
  for (const std::string option : {"--save", "--stats", "--trace", "--events"}) {
    const CliResult r = run_cli(
        {"run", "pyramid", "--steps", "2", "--no-render", option, (plain / "x.out").string()});
    EXPECT_EQ(r.code, mink::cli::kOutputFailure) << option << ": " << r.err;
    EXPECT_NE(r.err.find("'" + plain.string() + "'"), std::string::npos) << r.err;
  }
  const CliResult video = run_cli(
      {"run", "pyramid", "--steps", "2", "--size", "64x64", "--video", (plain / "x.mp4").string()});
  EXPECT_EQ(video.code, mink::cli::kOutputFailure) << video.err;
  EXPECT_NE(video.err.find("video '" + (plain / "x.mp4").string() + "'"), std::string::npos)
      << video.err;
}

}  // namespace
