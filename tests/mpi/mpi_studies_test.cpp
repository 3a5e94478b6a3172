// The studies under mpirun (docs/scaling.md; built with FLEXURE_MPI=ON): the file written by 1, 2
// and 3 ranks holds the same datasets, bit for bit, as the serial run's (the same binary started
// without mpirun, and the serial build's binary when FLEXURE_SERIAL_BINARY names it); a rank that
// fails, a rank that is killed and Ctrl-C end the run with a clear message, a non-zero exit and no
// file; commands that do not divide their work are refused. The machine has 2 cores: 3 ranks run
// oversubscribed. Open MPI refuses root unless told: the environment below allows it.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <thread>

#include "flexure/io/platform/output_path.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

// mpirun with a time limit: a hang fails the test instead of stalling the suite.
// Open MPI's variables that allow root (CI runs as root).
const std::string kAllowRoot = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ";

std::string mpirun(int ranks, const std::string& env = {}) {
  return "env " + kAllowRoot + env + " timeout 300 mpirun -np " + std::to_string(ranks) +
         " --oversubscribe ";
}

// Every dataset of a file (path -> class, raw bytes or strings).
struct Contents {
  std::map<std::string, std::string> numeric;  // raw bytes in the native type
  std::map<std::string, std::vector<std::string>> text;
  std::map<std::string, std::string> root_attributes;  // printed values
};

herr_t visit(hid_t object, const char* name, const H5O_info_t* info, void* data) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  auto& c = *static_cast<Contents*>(data);
  const hid_t d = H5Dopen2(object, name, H5P_DEFAULT);
  const hid_t type = H5Dget_type(d);
  if (H5Tget_class(type) == H5T_STRING) {
    c.text[name] = read_strings(object, name);
  } else {
    const hid_t native = H5Tget_native_type(type, H5T_DIR_ASCEND);
    const hid_t space = H5Dget_space(d);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    std::string bytes(static_cast<std::size_t>(n) * H5Tget_size(native), '\0');
    if (n > 0) H5Dread(d, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
    int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    std::string shape;
    for (hsize_t x : dims) shape += std::to_string(x) + "x";
    c.numeric[name] = shape + ":" + bytes;
    H5Sclose(space);
    H5Tclose(native);
  }
  H5Tclose(type);
  H5Dclose(d);
  return 0;
}

herr_t visit_attribute(hid_t object, const char* name, const H5A_info_t*, void* data) {
  auto& c = *static_cast<Contents*>(data);
  const hid_t a = H5Aopen(object, name, H5P_DEFAULT);
  const hid_t type = H5Aget_type(a);
  std::string value;
  if (H5Tget_class(type) == H5T_STRING) {
    value = read_string_attribute(object, "/", name);
  } else if (H5Tget_class(type) == H5T_INTEGER) {
    value = std::to_string(read_int_attribute(object, "/", name));
  } else {
    value = std::to_string(read_double_attribute(object, "/", name));
  }
  c.root_attributes[name] = value;
  H5Tclose(type);
  H5Aclose(a);
  return 0;
}

Contents contents(const std::filesystem::path& path) {
  Contents c;
  const hid_t f = open_read_only(path);
  EXPECT_GE(f, 0) << path;
  if (f < 0) return c;
  H5Ovisit(f, H5_INDEX_NAME, H5_ITER_INC, visit, &c);
  H5Aiterate2(f, H5_INDEX_NAME, H5_ITER_INC, nullptr, visit_attribute, &c);
  H5Fclose(f);
  return c;
}

// The same datasets bit for bit, the same root attributes but those that say when, how and by how
// many ranks the file was written; `ranks` checked in mpi_ranks.
void expect_same_file(const std::filesystem::path& reference,
                      const std::filesystem::path& candidate,
                      long long ranks,
                      const std::set<std::string>& timing = {}) {
  Contents a = contents(reference);
  Contents b = contents(candidate);
  ASSERT_FALSE(a.numeric.empty());
  for (const std::string& name : timing) {
    ASSERT_EQ(a.numeric.count(name), 1u) << name;
    a.numeric.erase(name);
    b.numeric.erase(name);
  }
  EXPECT_EQ(b.root_attributes["mpi_ranks"], std::to_string(ranks)) << candidate;
  for (const char* varying : {"mpi_ranks", "creation_time", "command_line"}) {
    a.root_attributes.erase(varying);
    b.root_attributes.erase(varying);
  }
  EXPECT_EQ(a.root_attributes, b.root_attributes) << candidate;
  ASSERT_EQ(a.numeric.size(), b.numeric.size()) << candidate;
  for (const auto& [name, bytes] : a.numeric) {
    ASSERT_EQ(b.numeric.count(name), 1u) << name;
    EXPECT_TRUE(bytes == b.numeric[name]) << "dataset " << name << " differs in " << candidate;
  }
  EXPECT_EQ(a.text, b.text) << candidate;
}

// Runs `args` serially and under 1, 2 and 3 ranks; the files must agree, and every run ends with
// `exit_code` and the same report (the first failure's message with exit 3).
// With `same_report`, stdout too must be the same (a report without timings). With
// `check_balance` = the number of items, every rank must have computed some of them.
void expect_ranks_agree(const std::string& args,
                        int exit_code = 0,
                        const std::set<std::string>& timing = {},
                        bool same_report = false,
                        long check_balance = 0,
                        const std::vector<int>& ranks = {1, 2, 3}) {
  ScratchDir dir;
  const CommandResult serial = run_flexure(args + " --out serial.h5", dir.path());
  ASSERT_EQ(serial.exit_code, exit_code) << serial.err;
  if (const char* other = std::getenv("FLEXURE_SERIAL_BINARY"); other != nullptr && *other) {
    // The serial build (FLEXURE_MPI=OFF): the same file.
    const std::string command = "cd '" + dir.path().string() + "' && '" + other + "' " + args +
                                " --out serial_build.h5 >/dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()) == 0, serial.exit_code == 0);
    expect_same_file(dir / "serial.h5", dir / "serial_build.h5", 1, timing);
  }
  for (int n : ranks) {
    const std::string out = "ranks" + std::to_string(n) + ".h5";
    const CommandResult r = run_flexure(args + " --out " + out, dir.path(), mpirun(n));
    EXPECT_EQ(r.exit_code, serial.exit_code) << n << " ranks: " << r.err;
    if (n > 1 && check_balance > 0) {
      // Every rank took part: "flexure: N ranks; items per rank: a, b, c" with each count > 0.
      const std::size_t at = r.err.find("items per rank: ");
      ASSERT_NE(at, std::string::npos) << r.err;
      std::istringstream counts(r.err.substr(at + 16, r.err.find('\n', at) - at - 16));
      long total = 0, ranks_seen = 0;
      for (std::string item; std::getline(counts, item, ',');) {
        EXPECT_GT(std::stol(item), 0) << r.err;
        total += std::stol(item);
        ++ranks_seen;
      }
      EXPECT_EQ(ranks_seen, n) << r.err;
      EXPECT_EQ(total, check_balance) << r.err;
    }
    // Rank 0 alone prints the report.
    EXPECT_EQ(count_lines(r.out), count_lines(serial.out)) << n << " ranks: " << r.out;
    if (same_report) {
      // The report names the output file; the rest must be the same.
      std::string expected = serial.out;
      for (std::size_t at = 0; (at = expected.find("serial.h5", at)) != std::string::npos;) {
        expected.replace(at, 9, out);
        at += out.size();
      }
      EXPECT_EQ(r.out, expected) << n << " ranks";
    }
    if (exit_code == 3) {
      // The message names the file; the rest must be the same.
      std::string first = serial.err.substr(0, serial.err.find('\n'));
      first = first.substr(first.find("the first is"));
      EXPECT_NE(r.err.find(first), std::string::npos) << n << " ranks: " << r.err;
    }
    expect_same_file(dir / "serial.h5", dir / out, n, timing);
  }
}

TEST(MpiStudies, SweepBeamUnevenSplitOverRanksIsTheSerialFile) {
  // 10 001 points (73 x 137): not a multiple of 2 or 3 ranks, nor of the block size (the last of
  // about ten blocks of the 1024-load minimum for elliptic is partial).
  expect_ranks_agree("sweep beam --alpha2 0:6:10001 --n 1 --method elliptic", 0, {}, false, 10001);
}

TEST(MpiStudies, SmallSweepOfCheapLoadsKeepsEveryRankBusy) {
  // 1000 elliptic loads (about a microsecond each; blocks of at least 1024 loads before, so that
  // one of two ranks computed all 1000): every rank computes some, and the file is the serial one.
  expect_ranks_agree("sweep beam --alpha2 0:10:1000 --method elliptic", 0, {}, false, 1000, {2, 3});
}

TEST(MpiStudies, SweepBeamGridWithFailedPointsIsTheSerialFile) {
  // A grid over alpha2 x mu with the chain algorithm, where 8 of the 12 loads do not converge:
  // the status dataset, the NaNs and the first failure (exit 3, its message) must be the same.
  expect_ranks_agree("sweep beam --method chain --n 1 --mu 28:30:2 --alpha2 0:-50:6", 3);
}

TEST(MpiStudies, MapCfmExactIsTheSerialFile) {
  expect_ranks_agree(
      "map cfm --config lps --R 0.6:2.4:7 --d 15:45:4 --K2 1.5 --model exact", 0, {}, false, 28);
}

TEST(MpiStudies, MapCfmPrbmGridIsTheSerialFile) {
  expect_ranks_agree("map cfm --config sss --R 0.5:3:41 --d 10:60:11 --K1 0.5:4:5 --K2 0.5:3:5");
}

TEST(MpiStudies, MapCfmJsonReportIsTheSerialOne) {
  // The summary (counts and the best point over all ranks) printed by rank 0.
  expect_ranks_agree(
      "map cfm --config sss --R 0.5:3:21 --d 10:60:6 --K1 0.5:4:3 --K2 0.5:3:3 --json",
      0,
      {},
      true);
}

TEST(MpiStudies, DesignAllSubclassesExactIsTheSerialTable) {
  // Each row re-optimised against the exact model on whichever rank takes it: the same optimum.
  // `seconds` (wall time per row) is the one dataset that cannot agree.
  expect_ranks_agree(
      "design cfm --all-subclasses --config spp --model exact", 0, {"seconds"}, false, 7);
}

TEST(MpiStudies, DesignAllSubclassesPrbmIsTheSerialTable) {
  expect_ranks_agree("design cfm --all-subclasses", 0, {"seconds"});
}

TEST(MpiStudies, MechanismValidateAllIsTheSerialTableAndReport) {
  expect_ranks_agree("mechanism validate --designs all --json", 0, {}, true);
}

TEST(MpiStudies, MechanismToleranceIsTheSerialFile) {
  // The central differences and the samples divided over the ranks (one analysis per item); the
  // draws made up front from the one seed: the file and the JSON report of 2 and 3 ranks are the
  // serial ones, bit for bit. 2 x 5 + 12 = 22 items, every rank computing some.
  expect_ranks_agree(
      "mechanism tolerance 1A-lpp --samples 12 --thickness 3% --E 2% --force-of whole --json",
      0,
      {},
      true,
      22,
      {2, 3});
}

TEST(MpiStudies, FailingRankEndsTheRunWithItsItemAndNoFile) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "map cfm --config lps --R 0.6:2.4:7 --d 15:45:4 --K2 1.5 --model exact --json "
      "--out map.h5",
      dir.path(),
      mpirun(3, "FLEXURE_FAIL_ITEM=17"));
  EXPECT_EQ(r.exit_code, 4) << r.err;  // an internal error (kExitInternal)
  EXPECT_NE(r.err.find("failed on item"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("item 17"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rank "), std::string::npos) << r.err;
  EXPECT_TRUE(dir.entries().empty()) << "left behind: " << dir.entries().front();
  // --json: the JSON error object on stdout.
  EXPECT_NE(r.out.find("\"error\""), std::string::npos) << r.out;
}

// Starts `command` in its own process group and returns its pid.
pid_t start(const std::string& command) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

// The pid of the rank `rank` running with `marker` on its command line, or -1.
pid_t find_rank(int rank, const std::string& marker) {
  const std::string want = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string cmdline = read_text(entry.path() / "cmdline");
    if (cmdline.rfind(FLEXURE_BINARY, 0) != 0 || cmdline.find(marker) == std::string::npos) {
      continue;
    }
    std::string environ = read_text(entry.path() / "environ");
    std::replace(environ.begin(), environ.end(), '\0', '\n');
    if (("\n" + environ).find("\n" + want + "\n") != std::string::npos) return std::stoi(name);
  }
  return -1;
}

// Waits up to `seconds` for `pid`; its exit status, or -1 (then it is killed).
int wait_for(pid_t pid, double seconds, bool& signalled) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      signalled = WIFSIGNALED(status);
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::kill(-pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return -1;
}

// Starts a 3-rank exact map long enough to be interrupted (about 30 s of work) once its temporary
// file exists, then calls `interrupt` with mpirun's pid.
void interrupt_a_run(const std::function<void(pid_t, const std::string&)>& interrupt,
                     const std::string& expect_in_err) {
  ScratchDir dir;
  const std::string marker = (dir / "map.h5").string();
  const std::string err =
      (dir.path().parent_path() / (dir.path().filename().string() + ".err")).string();
  // mpirun itself (exec), so that the signal goes to it as Ctrl-C on a terminal would.
  const pid_t mpirun_pid = start("cd '" + dir.path().string() + "' && exec env " + kAllowRoot +
                                 "mpirun -np 3 --oversubscribe '" + FLEXURE_BINARY +
                                 "' map cfm --config lps --R 0.6:2.4:60 --d 15:45:60 --K2 1.5 "
                                 "--model exact --exact-points 200 --out '" +
                                 marker + "' 2>'" + err + "'");
  // Wait until the ranks work: the temporary file is there.
  bool started = false;
  for (int i = 0; i < 400 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    started = !dir.entries().empty() && find_rank(1, marker) > 0;
  }
  ASSERT_TRUE(started) << "the run did not start";
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  interrupt(mpirun_pid, marker);
  bool signalled = false;
  const int code = wait_for(mpirun_pid, 60.0, signalled);
  const std::string message = read_text(err);
  std::filesystem::remove(err);
  EXPECT_NE(code, -1) << "the run did not end within 60 s (a hang)";
  EXPECT_NE(code, 0) << message;
  EXPECT_NE(message.find(expect_in_err), std::string::npos) << message;
  // Rank 0 names what the ranks were on.
  EXPECT_NE(message.find("blocks in progress when the run was stopped: rank "), std::string::npos)
      << message;
  const std::vector<std::string> left = dir.entries();
  EXPECT_TRUE(left.empty()) << "left behind: " << left.front();
}

TEST(MpiStudies, KilledRankEndsTheRunWithoutAFile) {
  interrupt_a_run(
      [](pid_t, const std::string& marker) {
        const pid_t rank1 = find_rank(1, marker);
        ASSERT_GT(rank1, 0);
        ::kill(rank1, SIGKILL);
      },
      // Rank 0 names the block the killed rank was computing (it never reported it finished).
      "rank 1 items ");
}

TEST(MpiStudies, TemporaryOfAKilledMpirunIsRemovedByTheNextRun) {
  // kill -9 of mpirun takes the ranks down without their handlers: the temporary stays. The next
  // run to the same file (here under mpirun too) recognises it by the pid and host in its name and
  // removes it, since that process is gone (docs/scaling.md "Failures").
  ScratchDir dir;
  const std::string marker = (dir / "k.h5").string();
  // About 45 s of work on 2 ranks (an exact map): a shooting sweep of 100000 loads once took a few
  // seconds, but faster solves finished it before the kill (the file then existed whole).
  const pid_t mpirun_pid = start("cd '" + dir.path().string() + "' && exec env " + kAllowRoot +
                                 "mpirun -np 2 --oversubscribe '" + FLEXURE_BINARY +
                                 "' map cfm --config lps --R 0.6:2.4:60 --d 15:45:60 --K2 1.5 "
                                 "--model exact --exact-points 200 --out '" +
                                 marker + "' >/dev/null 2>&1");
  bool started = false;
  for (int i = 0; i < 400 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    started = !dir.entries().empty() && find_rank(1, marker) > 0;
  }
  ASSERT_TRUE(started) << "the run did not start";
  const pid_t rank0 = find_rank(0, marker);
  ::kill(mpirun_pid, SIGKILL);
  int status = 0;
  ::waitpid(mpirun_pid, &status, 0);
  // The ranks end with mpirun (within seconds); the temporary of rank 0 stays behind.
  for (int i = 0; i < 200 && (find_rank(0, marker) > 0 || find_rank(1, marker) > 0); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_LT(find_rank(0, marker), 0) << "rank 0 outlived mpirun";
  const std::vector<std::string> left = dir.entries();
  ASSERT_EQ(left.size(), 1u);
  // ".k.h5.PID-SERIAL@HOST.tmp", PID being rank 0's.
  EXPECT_EQ(left[0].rfind(".k.h5." + std::to_string(rank0) + "-", 0), 0u) << left[0];
  EXPECT_NE(left[0].find("@" + io::temporary_host_tag() + ".tmp"), std::string::npos) << left[0];
  const CommandResult next =
      run_flexure("sweep beam --alpha2 0:10:100 --out k.h5", dir.path(), mpirun(2));
  ASSERT_EQ(next.exit_code, 0) << next.err;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"k.h5"});
}

TEST(MpiStudies, CtrlCEndsEveryRankWithoutAFile) {
  interrupt_a_run([](pid_t mpirun_pid, const std::string&) { ::kill(mpirun_pid, SIGINT); }, "");
}

TEST(MpiStudies, CommandsThatDoNotDivideTheirWorkAreRefused) {
  const CommandResult r = run_flexure("beam --alpha2 1", {}, mpirun(2));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("does not divide its work over MPI ranks"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// How often `text` occurs in `in`.
int occurrences(const std::string& in, const std::string& text) {
  int n = 0;
  for (std::size_t at = 0; (at = in.find(text, at)) != std::string::npos; at += text.size()) ++n;
  return n;
}

TEST(MpiStudies, WarningsAndErrorsEveryRankMeetsArePrintedOnce) {
  // A warning on the input (7 rad is more than a full turn), printed once by rank 0, and an error
  // on one of its loads (no equilibrium for that tip angle), printed once by the rank that met it:
  // exit 2 as in the serial run, no file. One load of the two is invalid: since every rank
  // starts with a load of its own, several invalid loads would be met by several ranks at once,
  // each printing its own before the abort (docs/scaling.md "Failures").
  ScratchDir dir;
  const std::string args = "sweep beam --theta0 0.1:7:2 --n 1 --method elliptic --out s.h5";
  const CommandResult serial = run_flexure(args, dir.path());
  ASSERT_EQ(serial.exit_code, 2) << serial.err;
  const CommandResult r = run_flexure(args, dir.path(), mpirun(3));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(occurrences(r.err, "more than a full turn"), 1) << r.err;
  EXPECT_EQ(occurrences(r.err, "cannot be reached"), 1) << r.err;
  // The serial message (the load is an item: under mpirun the rank that met it names it).
  EXPECT_NE(r.err.find(serial.err.substr(serial.err.find("at theta0 ="))), std::string::npos)
      << r.err << "\nserial:\n"
      << serial.err;
  EXPECT_TRUE(dir.entries().empty());
}

TEST(MpiStudies, RankZeroPrintsProgressOverAllRanks) {
  // Progress lines every 0.2 s (FLEXURE_PROGRESS_SECONDS) on a map of 200 exact strokes (about 1 s
  // over 2 ranks): "map cfm lps: k/200 (p %, t s, 2 ranks)", k counting the items of both ranks,
  // never falling, up to 200.
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "map cfm --config lps --R 0.6:2.4:20 --d 15:45:10 --K2 1.5 --model exact "
      "--exact-points 200 --out map.h5",
      dir.path(),
      mpirun(2, "FLEXURE_PROGRESS_SECONDS=0.2"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.err);
  long last = -1;
  int count = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("map cfm lps: ", 0) != 0) continue;
    ++count;
    const long done = std::stol(line.substr(13));
    EXPECT_NE(line.find("/200 ("), std::string::npos) << line;
    EXPECT_NE(line.find(", 2 ranks)"), std::string::npos) << line;
    EXPECT_GE(done, last) << r.err;
    EXPECT_LE(done, 200) << line;
    last = done;
  }
  EXPECT_GE(count, 2) << r.err;
}

TEST(MpiStudies, SpringRulesAreRefusedUnderSeveralRanks) {
  // validate --spring-rules does not divide its work: each rank would run it whole.
  const CommandResult r = run_flexure("mechanism validate --spring-rules", {}, mpirun(2));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'flexure mechanism validate --spring-rules' does not divide"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// Which rank computed each item in each round of distribution_probe's run (round -> item ->
// rank); every item exactly once per round.
std::map<int, std::map<long, int>> probe(int ranks, const std::string& args) {
  ScratchDir dir;
  const std::string command = mpirun(ranks) + "'" + FLEXURE_DISTRIBUTION_PROBE + "' " + args +
                              " >'" + (dir / "out").string() + "' 2>'" + (dir / "err").string() +
                              "'";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << read_text(dir / "err");
  std::map<int, std::map<long, int>> rank_of;
  std::istringstream lines(read_text(dir / "out"));
  int round = 0;
  long item = 0;
  int rank = 0;
  while (lines >> round >> item >> rank) {
    EXPECT_EQ(rank_of[round].count(item), 0u) << "item " << item << " computed twice";
    rank_of[round][item] = rank;
  }
  return rank_of;
}

TEST(MpiStudies, ASlowItemKeepsItsRankToItself) {
  // Items that each make a block of their own (designs, optimisations): a rank is given its next
  // item only once it is free. Rank 1's first item takes 1 s, every other 0.1 s: ranks 0 and 2
  // share the other seven while rank 1 is busy, and rank 1 takes no second item. Were the next
  // item given ahead, it would wait behind the slow one and end the run 0.1 s later.
  const std::map<long, int> rank_of = probe(3, "8 1 1 1.0 0.1")[0];
  ASSERT_EQ(rank_of.size(), 8u);
  int on_rank_1 = 0;
  for (const auto& [item, rank] : rank_of) on_rank_1 += rank == 1;
  EXPECT_EQ(on_rank_1, 1);
}

TEST(MpiStudies, BlocksOfManyItemsCoverEveryItemOnceRoundAfterRound) {
  // Blocks of up to 16 items, given ahead while many are left, shrinking to single items: each of
  // 1001 items computed exactly once, by every one of the 3 ranks; three distributions in a row
  // (a worker's first request of the next must not reach rank 0 while it still answers this one).
  const std::map<int, std::map<long, int>> rounds = probe(3, "1001 16 -1 0 0.0002 3");
  ASSERT_EQ(rounds.size(), 3u);
  for (const auto& [round, rank_of] : rounds) {
    ASSERT_EQ(rank_of.size(), 1001u) << "round " << round;
    EXPECT_EQ(rank_of.begin()->first, 0);
    EXPECT_EQ(rank_of.rbegin()->first, 1000);
    std::set<int> ranks;
    for (const auto& [item, rank] : rank_of) ranks.insert(rank);
    EXPECT_EQ(ranks.size(), 3u) << "round " << round;
  }
}

TEST(MpiStudies, CtrlCWithoutAnOutputFileNamesTheBlocksInProgress) {
  // design cfm --all-subclasses --model exact writes no file without --out: the handlers that
  // name the blocks are installed by the distribution itself. About 15 s of work on 3 ranks.
  ScratchDir dir;
  const std::string err = (dir / "err").string();
  const pid_t mpirun_pid =
      start("exec env " + kAllowRoot + "mpirun -np 3 --oversubscribe '" + FLEXURE_BINARY +
            "' design cfm --all-subclasses --config lps --model exact "
            "--exact-starts 4 2>'" +
            err + "' >/dev/null");
  bool started = false;
  for (int i = 0; i < 400 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    started = find_rank(1, "--all-subclasses") > 0;
  }
  ASSERT_TRUE(started) << "the run did not start";
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(mpirun_pid, SIGINT);
  bool signalled = false;
  const int code = wait_for(mpirun_pid, 60.0, signalled);
  const std::string message = read_text(err);
  EXPECT_NE(code, -1) << "the run did not end within 60 s (a hang)";
  EXPECT_NE(code, 0) << message;
  EXPECT_NE(message.find("blocks in progress when the run was stopped: rank "), std::string::npos)
      << message;
}

TEST(MpiStudies, CompressIsRefusedUnderSeveralRanks) {
  ScratchDir dir;
  const CommandResult r =
      run_flexure("sweep beam --alpha2 0:1:11 --compress --out s.h5", dir.path(), mpirun(2));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--compress is not available under mpirun"), std::string::npos) << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace flexure::test
