// What is checked against what (output files, docs/cli.md):
// - the temporary name AtomicHdf5File writes fits the file-name limit for any target name that
//   fits it itself (a 251-byte target name failed: its temporary name was over 255 bytes), in the
//   target's directory, cut at a UTF-8 character boundary; such a target is written and renamed;
// - io::output_path_problem names the reason for a name over NAME_MAX, a path over PATH_MAX, a
//   missing directory, a directory, FIFO or other non-regular file in place of the target, and -
//   in a child process switched to the unprivileged user nobody - an existing file of another
//   user in a sticky directory (rename() would fail with EPERM); and accepts a file of its own
//   there;
// - every command that takes --out (sweep beam, path, validate, mechanism analyze, dynamics,
//   bench) exits 2 before any work, naming the path and the reason; for a sweep that would take
//   about a minute (5000 shooting solves, about 12 ms each) the refusal comes in seconds, for a
//   directory in place of the target and, run as nobody, for another user's file in a sticky
//   directory (found only by the rename after the whole sweep before);
// - temporaries left by killed processes (kill -9: no handler runs) are recognised by the pid and
//   host in their name and removed by the next writer of that directory: those of processes that
//   are gone or whose number a younger process now has; those of live processes, of other hosts
//   and files of other forms stay. A `sweep beam` killed with SIGKILL leaves its temporary, and
//   the next run to the same --out leaves only its file (issue 27).
#include "flexure/io/platform/output_path.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::io {
namespace {

using test::run_flexure;
using test::ScratchDir;

constexpr uid_t kNobody = 65534;

// Every command that writes --out, with arguments that are otherwise valid; OUT is replaced.
const char* const kOutCommands[] = {
    "sweep beam --alpha2 0:1:3 --out OUT",
    "path --alpha2 1 --out OUT",
    "validate --out OUT",
    "mechanism analyze 1A-lpp --points 3 --out OUT",
    "dynamics --mechanism 2B-lplm --omega 0:1:2 --out OUT",
    "bench --quick --problems tip_moment --methods elliptic,prbm --out OUT",
};

std::string with_out(std::string command, const std::string& out) {
  return command.replace(command.find("OUT"), 3, "'" + out + "'");
}

TEST(OutputPath, TemporaryNameFitsTheLimitInTheTargetsDirectory) {
  // A short name keeps its whole name in the temporary.
  EXPECT_EQ(temporary_path_for("dir/out.h5", 123, 7, 255), "dir/.out.h5.123-7.tmp");
  EXPECT_EQ(temporary_path_for("out.h5", 123, 7, 255), ".out.h5.123-7.tmp");
  // A name at the limit: the temporary keeps as much of it as fits.
  const std::string longest(255, 'x');
  const std::filesystem::path temp =
      temporary_path_for("/a/b/" + longest, 4194304, 4294967295u, 255);
  EXPECT_EQ(temp.parent_path(), "/a/b");
  EXPECT_EQ(temp.filename().string().size(), 255u);
  EXPECT_EQ(temp.filename().string().rfind(".4194304-4294967295.tmp"), 255u - 23u);
  // A cut never splits a UTF-8 character: 'é' is two bytes, so an odd cut backs up one byte.
  std::string accents;
  for (int i = 0; i < 120; ++i) accents += "\xC3\xA9";
  const std::string cut = std::filesystem::path(temporary_path_for(accents, 1, 0, 21)).filename();
  // 21 - ".1-0.tmp" (8) - "." (1) = 12 bytes of name: six whole characters.
  EXPECT_EQ(cut, "." + accents.substr(0, 12) + ".1-0.tmp");
  const std::string odd = std::filesystem::path(temporary_path_for(accents, 1, 0, 22)).filename();
  EXPECT_EQ(odd, "." + accents.substr(0, 12) + ".1-0.tmp") << "13 bytes would split a character";
}

TEST(OutputPath, TemporaryNameRecordsPidAndHost) {
  EXPECT_EQ(temporary_path_for("dir/out.h5", 123, 7, 255, "node1"), "dir/.out.h5.123-7@node1.tmp");
  // The name is cut, never the pid, serial or host.
  EXPECT_EQ(temporary_path_for("abcdefghij", 1, 0, 20, "h"), ".abcdefghi.1-0@h.tmp");
  const std::string host = temporary_host_tag();
  EXPECT_FALSE(host.empty());
  EXPECT_LE(host.size(), 32u);
  EXPECT_EQ(
      host.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_"),
      std::string::npos)
      << host;
}

// A pid that no process has: a child that has exited and been reaped.
pid_t gone_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

void touch(const std::filesystem::path& path, double seconds_ago = 0.0) {
  std::ofstream(path) << "x";
  if (seconds_ago > 0.0) {
    const auto when = std::filesystem::last_write_time(path) -
                      std::chrono::duration_cast<std::filesystem::file_time_type::duration>(
                          std::chrono::duration<double>(seconds_ago));
    std::filesystem::last_write_time(path, when);
  }
}

TEST(OutputPath, StaleTemporariesOfGoneProcessesAreRemoved) {
  ScratchDir dir;
  const std::string host = temporary_host_tag();
  const std::string dead = std::to_string(gone_pid());
  // A live process that started now: a temporary written an hour ago cannot be its own (its pid
  // was reused), one written now can.
  const pid_t child = ::fork();
  if (child == 0) {
    ::sleep(30);
    ::_exit(0);
  }
  // A process that has ended but is not reaped yet (a zombie: the ranks of a killed mpirun where
  // no init reaps them) is gone too, though kill(pid, 0) still finds it.
  const pid_t zombie = ::fork();
  if (zombie == 0) ::_exit(0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const std::string live = std::to_string(child);
  const std::vector<std::string> removed_names = {
      ".out.h5." + dead + "-0@" + host + ".tmp",    // this target, process gone
      ".other.h5." + dead + "-2@" + host + ".tmp",  // another target in the directory, gone
      ".out.h5." + dead + "-1.tmp",                 // this target, the name without a host
      ".out.h5." + std::to_string(zombie) + "-0@" + host + ".tmp",  // ended, not reaped
  };
  const std::vector<std::string> kept_names = {
      ".other.h5." + dead + "-1.tmp",             // without a host: only this target's
      ".out.h5." + dead + "-0@another-host.tmp",  // another host: its pids say nothing here
      ".out.h5." + live + "-0@" + host + ".tmp",  // a live writer
      ".out.h5.1-0@" + host + ".tmp",             // pid 1 is alive and older than the file
      ".out.h5.x1-0@" + host + ".tmp",            // not a pid
      "notes.tmp",
      "out.h5",
  };
  for (const std::string& name : removed_names) touch(dir / name);
  for (const std::string& name : kept_names) touch(dir / name);
  const std::string reused = ".out.h5." + live + "-5@" + host + ".tmp";
  touch(dir / reused, 3600.0);
  std::vector<std::string> removed = remove_stale_temporaries((dir / "out.h5").string());
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  ::waitpid(zombie, nullptr, 0);
  for (std::string& path : removed) path = std::filesystem::path(path).filename().string();
  std::sort(removed.begin(), removed.end());
  std::vector<std::string> expected = removed_names;
  expected.push_back(reused);
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(removed, expected);
  std::vector<std::string> left = dir.entries();
  std::sort(left.begin(), left.end());
  std::vector<std::string> kept = kept_names;
  std::sort(kept.begin(), kept.end());
  EXPECT_EQ(left, kept);
}

TEST(OutputPath, ATargetNameAtTheLimitIsWrittenAndNothingElseIsLeft) {
  ScratchDir dir;
  const long limit = file_name_limit(dir.path().string());
  const std::string name = std::string(static_cast<std::size_t>(limit) - 3, 'n') + ".h5";
  {
    AtomicHdf5File file((dir / name).string());
    EXPECT_LE(std::filesystem::path(file.temp_path()).filename().string().size(),
              static_cast<std::size_t>(limit));
    file.root().set_attribute("x", 1.0);
    write_provenance(file.root(), {});
    file.commit();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{name});
  const hid_t file = test::open_read_only(dir / name);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_double_attribute(file, "/", "x"), 1.0);
  H5Fclose(file);
}

TEST(OutputPath, ProblemsAreNamed) {
  ScratchDir dir;
  const long limit = file_name_limit(dir.path().string());
  EXPECT_EQ(output_path_problem((dir / "ok.h5").string()), "");
  const std::string too_long = std::string(static_cast<std::size_t>(limit) + 1, 'x');
  const std::string message = output_path_problem((dir / too_long).string());
  EXPECT_NE(message.find(std::to_string(limit + 1) + " bytes"), std::string::npos) << message;
  EXPECT_NE(message.find("NAME_MAX"), std::string::npos) << message;
  // PATH_MAX: many short components, each within NAME_MAX.
  std::string deep = dir.path().string();
  while (deep.size() < PATH_MAX) deep += "/abcdefgh";
  EXPECT_NE(output_path_problem(deep + "/x.h5").find("PATH_MAX"), std::string::npos);
  EXPECT_NE(output_path_problem((dir / "missing" / "x.h5").string()).find("does not exist"),
            std::string::npos);
  std::filesystem::create_directory(dir / "sub");
  EXPECT_NE(output_path_problem((dir / "sub").string()).find("existing directory"),
            std::string::npos);
  EXPECT_NE(output_path_problem((dir / "sub").string() + "/").find("names a directory"),
            std::string::npos);
  ASSERT_EQ(::mkfifo((dir / "fifo.h5").c_str(), 0600), 0);
  EXPECT_NE(output_path_problem((dir / "fifo.h5").string()).find("a FIFO"), std::string::npos)
      << "rename() would replace the FIFO (as root, --out /dev/null would replace /dev/null)";
  try {
    check_output_path((dir / too_long).string(), "--out");
    FAIL() << "check_output_path accepted a name over NAME_MAX";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("--out '" + (dir / too_long).string() + "'"),
              std::string::npos)
        << e.what();
  }
}

// A scratch directory like /tmp: sticky, world-writable, owned by root, holding `name` owned by
// root. Only meaningful when the test runs as root (it then switches a child to nobody).
struct StickyDir {
  ScratchDir scratch;
  std::filesystem::path dir = scratch / "sticky";
  explicit StickyDir(const std::string& name) {
    std::filesystem::create_directory(dir);
    ::chmod(scratch.path().c_str(), 0755);  // mkdtemp made it 0700: let nobody in
    ::chmod(dir.c_str(), 01777);
    std::ofstream(dir / name) << "root's file";
  }
};

TEST(OutputPath, AnotherUsersFileInAStickyDirectoryIsRefused) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to act as another user";
  StickyDir sticky("theirs.h5");
  const std::string theirs = (sticky.dir / "theirs.h5").string();
  const std::string mine = (sticky.dir / "mine.h5").string();
  EXPECT_EQ(output_path_problem(theirs), "") << "root (CAP_FOWNER) may replace it";
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // As nobody: 1 = theirs accepted, 2 = wrong message, 3 = a new name of its own refused,
    // 4 = its own file refused, 5 = setuid failed; 0 = all as expected.
    if (::setgid(kNobody) != 0 || ::setuid(kNobody) != 0) ::_exit(5);
    const std::string problem = output_path_problem(theirs);
    if (problem.empty()) ::_exit(1);
    if (problem.find("sticky directory") == std::string::npos ||
        problem.find("uid 0") == std::string::npos) {
      ::_exit(2);
    }
    if (!output_path_problem(mine).empty()) ::_exit(3);
    const int fd = ::open(mine.c_str(), O_CREAT | O_WRONLY, 0600);
    if (fd < 0) ::_exit(3);
    ::close(fd);
    if (!output_path_problem(mine).empty()) ::_exit(4);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "see the codes in the child";
}

TEST(OutputPathCli, EveryOutCommandRefusesATooLongNameBeforeWorking) {
  ScratchDir dir;
  const long limit = file_name_limit(dir.path().string());
  const std::string out =
      (dir / (std::string(static_cast<std::size_t>(limit) - 2, 'x') + ".h5")).string();
  for (const char* command : kOutCommands) {
    const auto start = std::chrono::steady_clock::now();
    const test::CommandResult r = run_flexure(with_out(command, out));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("NAME_MAX"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << "the temporary name is ours, not theirs";
    EXPECT_LT(seconds, 5.0) << command;
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(OutputPathCli, EveryOutCommandRefusesADirectoryOrFifoInPlaceOfTheTarget) {
  ScratchDir dir;
  std::filesystem::create_directory(dir / "target.h5");
  ASSERT_EQ(::mkfifo((dir / "fifo.h5").c_str(), 0600), 0);
  for (const char* command : kOutCommands) {
    for (const char* name : {"target.h5", "fifo.h5"}) {
      const test::CommandResult r = run_flexure(with_out(command, (dir / name).string()));
      EXPECT_EQ(r.exit_code, 2) << command << " " << name << "\n" << r.err;
      EXPECT_NE(r.err.find((dir / name).string()), std::string::npos) << r.err;
    }
  }
  EXPECT_TRUE(std::filesystem::is_directory(dir / "target.h5"));
  EXPECT_TRUE(std::filesystem::is_fifo(dir / "fifo.h5")) << "the FIFO was replaced";
  EXPECT_EQ(dir.entries().size(), 2u) << "a temporary or checkpoint was left behind";
  // bench writes a checkpoint OUT.partial after every group: it is checked up front as well.
  std::filesystem::create_directory(dir / "b.h5.partial");
  const test::CommandResult r =
      run_flexure("bench --quick --out '" + (dir / "b.h5").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("b.h5.partial"), std::string::npos) << r.err;
}

// 5000 shooting solves on one thread, about a minute of work (12 ms each measured on the 2-core
// CI machine) before the rename if the path were checked only then.
const std::string kLongSweep = "sweep beam --method shooting --alpha2 0.1:10:5000 --threads 1";

TEST(OutputPathCli, ALongSweepIntoADirectoryReturnsAtOnce) {
  ScratchDir dir;
  std::filesystem::create_directory(dir / "out.h5");
  const auto start = std::chrono::steady_clock::now();
  const test::CommandResult r =
      run_flexure(kLongSweep + " --out '" + (dir / "out.h5").string() + "'");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("existing directory"), std::string::npos) << r.err;
  EXPECT_LT(seconds, 5.0);
}

TEST(OutputPathCli, ALongSweepOverAnotherUsersFileInAStickyDirectoryReturnsAtOnce) {
  if (::geteuid() != 0) GTEST_SKIP() << "needs root to act as another user";
  StickyDir sticky("theirs.h5");
  const std::string theirs = (sticky.dir / "theirs.h5").string();
  // setpriv (util-linux) runs the tool as nobody; stdout and stderr are redirected by the shell
  // (root) before it switches.
  const auto start = std::chrono::steady_clock::now();
  const test::CommandResult r = run_flexure(kLongSweep + " --out '" + theirs + "'",
                                            {},
                                            "setpriv --reuid=65534 --regid=65534 --clear-groups ");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(theirs), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sticky directory"), std::string::npos) << r.err;
  EXPECT_LT(seconds, 5.0);
  EXPECT_EQ(test::read_text(theirs), "root's file");
}

TEST(OutputPathCli, ARunKilledWithSigkillIsCleanedUpByTheNextRun) {
  ScratchDir dir;
  // A sweep of about a minute, killed once its temporary exists: no handler runs.
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string command = "cd '" + dir.path().string() + "' && exec '" + FLEXURE_BINARY +
                                "' " + kLongSweep + " --out k.h5 >/dev/null 2>&1";
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  bool started = false;
  for (int i = 0; i < 200 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    started = !dir.entries().empty();
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  ASSERT_TRUE(started);
  const std::vector<std::string> left = dir.entries();
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].rfind(".k.h5." + std::to_string(pid) + "-", 0), 0u) << left[0];
  // The next run to the same file removes it and leaves only its own result.
  const test::CommandResult r = run_flexure("sweep beam --alpha2 0:1:3 --out k.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"k.h5"});
}

}  // namespace
}  // namespace flexure::io
