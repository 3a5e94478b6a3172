// What is checked against what (`flexure bench` stopped by a signal, the built binary):
//  - SIGINT after the first finished group (its checkpoint FILE.partial appears on disk): the
//    process still dies by SIGINT, FILE.partial is kept, FILE is not written, and stderr names the
//    checkpoint and the exact command to resume (this program, the same --out, --problems,
//    --methods, and --resume);
//  - a rerun without --resume refuses (exit 2) and keeps the checkpoint;
//  - the printed command, run as printed, finishes the run reusing the checkpointed group: exit 0,
//    FILE written, FILE.partial removed, "1 reused";
//  - a run stopped by --stop-after names the same command (JSON resume_command), null once the
//    run completes.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::read_text;
using test::ScratchDir;

// The reference group of fixed_guided takes about 2 s here, the shooting group after it 1.4 s: the
// signal arrives while the second group is computed.
const char* kProblems = "fixed_guided";
const char* kMethods = "shooting_cvodes_rtol1e-06,prbm";

TEST(BenchInterruptCli, SigintSaysHowToResumeAndKeepsTheCheckpoint) {
  ScratchDir dir;
  const std::filesystem::path out = dir / "b.h5";
  const std::filesystem::path checkpoint = dir / "b.h5.partial";
  const std::filesystem::path err = dir / "stderr.txt";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::chdir(dir.path().c_str()) != 0) ::_exit(126);
    std::freopen("/dev/null", "w", stdout);
    std::freopen(err.c_str(), "w", stderr);
    ::execl(FLEXURE_BINARY,
            FLEXURE_BINARY,
            "bench",
            "--out",
            "b.h5",
            "--problems",
            kProblems,
            "--methods",
            kMethods,
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  bool seen = false;
  for (int i = 0; i < 6000 && !seen; ++i) {  // up to a minute on a loaded machine
    seen = std::filesystem::exists(checkpoint);
    if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(seen) << "no checkpoint after a minute:\n" << read_text(err);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
      << "the run finished before the signal, or did not die by it";
  EXPECT_TRUE(std::filesystem::exists(checkpoint)) << "the checkpoint must be kept";
  EXPECT_FALSE(std::filesystem::exists(out));

  const std::string message = read_text(err);
  EXPECT_NE(message.find("the finished groups are kept in b.h5.partial"), std::string::npos)
      << message;
  const std::string expected = std::string(FLEXURE_BINARY) + " bench --out b.h5 --problems " +
                               kProblems + " --methods " + kMethods + " --resume";
  const std::string marker = "Resume with:\n  ";
  const std::size_t at = message.find(marker);
  ASSERT_NE(at, std::string::npos) << message;
  const std::string command = message.substr(
      at + marker.size(), message.find('\n', at + marker.size()) - at - marker.size());
  EXPECT_EQ(command, expected);

  // Without --resume: refused, the checkpoint kept.
  const test::CommandResult again = test::run_flexure(
      std::string("bench --out b.h5 --problems ") + kProblems + " --methods " + kMethods,
      dir.path());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
  EXPECT_TRUE(std::filesystem::exists(checkpoint));

  // The printed command finishes the run.
  const std::filesystem::path log = dir / "resume.txt";
  const std::string shell =
      "cd '" + dir.path().string() + "' && " + command + " > '" + log.string() + "' 2>&1";
  const int resumed = std::system(shell.c_str());
  ASSERT_TRUE(WIFEXITED(resumed) && WEXITSTATUS(resumed) == 0) << read_text(log);
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(checkpoint));
  EXPECT_NE(read_text(log).find("1 reused"), std::string::npos) << read_text(log);
}

TEST(BenchInterruptCli, StopAfterNamesTheResumeCommand) {
  ScratchDir dir;
  const std::string select = "--quick --problems tip_moment --methods elliptic";
  const test::CommandResult stopped =
      test::run_flexure("bench --out s.h5 " + select + " --stop-after 1 --json", dir.path());
  ASSERT_EQ(stopped.exit_code, 0) << stopped.err;
  const nlohmann::json j = nlohmann::json::parse(stopped.out);
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_EQ(j["resume_command"],
            std::string(FLEXURE_BINARY) + " bench --out s.h5 " + select + " --json --resume");
  const std::string shell = "cd '" + dir.path().string() + "' && " +
                            j["resume_command"].get<std::string>() + " 2>/dev/null";
  FILE* pipe = ::popen(shell.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
  ASSERT_EQ(::pclose(pipe), 0) << out;
  const nlohmann::json done = nlohmann::json::parse(out);
  EXPECT_TRUE(done["complete"].get<bool>());
  EXPECT_TRUE(done["resume_command"].is_null());
  EXPECT_EQ(done["groups_reused"], 1);
}

}  // namespace
}  // namespace flexure
