// What is checked against what: a `flexure ... --out` run stopped by SIGTERM or SIGINT while it
// computes leaves nothing behind: its hidden temporary (seen in the directory before the signal)
// is removed by io/platform/temp_file_cleanup.h's handler, no target is created, and the process
// still dies by that signal (the handler re-raises it).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

int count_entries(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

// Starts a long `mechanism analyze --out` (many stroke points of the hardest built-in design),
// waits until its temporary appears, sends `signal_number`, and checks what is left.
void stop_and_check(int signal_number) {
  test::ScratchDir dir;
  const std::string out = (dir / "stroke.h5").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::execl(FLEXURE_BINARY,
            FLEXURE_BINARY,
            "mechanism",
            "analyze",
            "3A-lssm",
            "--method",
            "exact",
            "--points",
            "100000",
            "--out",
            out.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // The temporary is created before the computation starts (the writability check).
  bool seen = false;
  for (int i = 0; i < 500 && !seen; ++i) {
    seen = count_entries(dir.path()) > 0;
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, signal_number);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(seen) << "the run never created its temporary file";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number)
      << "the process must still die by the signal";
  EXPECT_EQ(count_entries(dir.path()), 0) << "temporary or partial file left behind";
}

TEST(AtomicHdf5FileSignal, SigtermRemovesTheTemporary) { stop_and_check(SIGTERM); }
TEST(AtomicHdf5FileSignal, SigintRemovesTheTemporary) { stop_and_check(SIGINT); }

}  // namespace
}  // namespace flexure
