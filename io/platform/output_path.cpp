#include "flexure/io/platform/output_path.h"

#include <fmt/format.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "flexure/io/platform/temp_file_cleanup.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

// The longest host tag in a temporary name (temporary_host_tag).
constexpr std::size_t kMaxHostTag = 32;
// The most a temporary name adds to the target's file name: "." + "." + a pid (up to 10 digits)
// + "-" + a serial (up to 10 digits) + "@" + the host tag + ".tmp".
constexpr std::size_t kTemporaryOverhead = 1 + 1 + 10 + 1 + 10 + 1 + kMaxHostTag + 4;

bool all_digits(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

// "PID-SERIAL" -> PID, or -1 when it is not of that form.
long pid_of(std::string_view pid_serial) {
  const std::size_t dash = pid_serial.find('-');
  if (dash == std::string_view::npos || !all_digits(pid_serial.substr(0, dash)) ||
      !all_digits(pid_serial.substr(dash + 1)) || dash > 10) {
    return -1;
  }
  return std::stol(std::string(pid_serial.substr(0, dash)));
}

// What /proc (Linux) says of process `pid`: its state letter (field 3: 'Z' a zombie, which has
// ended but was not yet reaped, as the ranks of a killed mpirun in a container whose init does not
// reap) and when it started, in seconds since the epoch (NaN when unknown).
struct ProcessInfo {
  char state = '?';
  double started = std::nan("");
};
ProcessInfo process_info(long pid) {
  ProcessInfo info;
  std::ifstream stat_file(fmt::format("/proc/{}/stat", pid));
  std::string line;
  if (!std::getline(stat_file, line)) return info;
  // Fields counted after the command name, which is in parentheses and may hold spaces: field 3
  // the state, field 22 starttime in clock ticks after boot.
  const std::size_t close = line.rfind(')');
  if (close == std::string::npos) return info;
  std::istringstream fields(line.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i) {
    if (i == 3) info.state = field.empty() ? '?' : field[0];
    if (i < 22) continue;
    std::ifstream proc_stat("/proc/stat");
    for (std::string row; std::getline(proc_stat, row);) {
      if (row.rfind("btime ", 0) == 0) {
        const double boot = std::stod(row.substr(6));
        info.started = boot + std::stod(field) / static_cast<double>(::sysconf(_SC_CLK_TCK));
      }
    }
  }
  return info;
}

// Whether the process that wrote a temporary last modified at `written` (seconds since the epoch)
// is gone: no process has its number, it has ended (a zombie), or the one that has it started
// after the file was written (the number was reused). A process of another user still counts as
// there (EPERM).
bool writer_gone(long pid, double written) {
  if (pid <= 0 || pid == static_cast<long>(::getpid())) return false;
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) return true;
  const ProcessInfo info = process_info(pid);
  if (info.state == 'Z' || info.state == 'X') return true;  // ended, not yet reaped
  // A margin of 2 s over the clock-tick and file-time granularity.
  return std::isfinite(info.started) && info.started > written + 2.0;
}

std::filesystem::path directory_of(const std::filesystem::path& path) {
  return path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
}

// Whether this process may replace entries of a sticky directory it does not own: CAP_FOWNER in
// the effective capability set (root normally has it). Read from /proc; without it, euid 0.
bool has_cap_fowner() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("CapEff:", 0) == 0) {
      unsigned long long mask = 0;
      std::istringstream(line.substr(7)) >> std::hex >> mask;
      constexpr int kCapFowner = 3;  // linux/capability.h
      return (mask >> kCapFowner) & 1ULL;
    }
  }
  return ::geteuid() == 0;
}

std::string user_name(uid_t uid) {
  std::vector<char> buffer(16384);
  struct passwd entry {};
  struct passwd* found = nullptr;
  if (::getpwuid_r(uid, &entry, buffer.data(), buffer.size(), &found) == 0 && found != nullptr) {
    return fmt::format("'{}' (uid {})", found->pw_name, uid);
  }
  return fmt::format("uid {}", uid);
}

const char* kind_of(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

long file_name_limit(const std::string& directory) {
  errno = 0;
  const long limit = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  return limit > 0 ? limit : NAME_MAX;
}

std::string temporary_host_tag() {
  char name[256] = {};
  std::string tag;
  if (::gethostname(name, sizeof name - 1) == 0) {
    for (const char* c = name; *c != '\0' && *c != '.' && tag.size() < kMaxHostTag; ++c) {
      if (std::isalnum(static_cast<unsigned char>(*c)) || *c == '-' || *c == '_') tag += *c;
    }
  }
  return tag.empty() ? std::string("localhost") : tag;
}

std::string temporary_path_for(
    const std::string& target, long pid, unsigned serial, long name_max, const std::string& host) {
  const std::filesystem::path path(target);
  const std::string suffix = host.empty() ? fmt::format(".{}-{}.tmp", pid, serial)
                                          : fmt::format(".{}-{}@{}.tmp", pid, serial, host);
  std::string name = path.filename().string();
  const std::size_t room =
      static_cast<std::size_t>(std::max(0L, name_max - 1 - static_cast<long>(suffix.size())));
  if (name.size() > room) {
    std::size_t cut = room;
    // Do not split a multi-byte UTF-8 character: back up over continuation bytes (10xxxxxx).
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
    name.resize(cut);
  }
  return (path.parent_path() / ("." + name + suffix)).string();
}

std::vector<std::string> remove_stale_temporaries(const std::string& target) {
  std::vector<std::string> removed;
  const std::filesystem::path path(target);
  const std::filesystem::path dir = directory_of(path);
  const std::string host = temporary_host_tag();
  // The host-less names of this target, ".NAME.": NAME as temporary_path_for cuts it is at most
  // the whole name, so a prefix of ".NAME." or of the cut name matches.
  const std::string name = path.filename().string();
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string file = it->path().filename().string();
    if (file.size() < 6 || file[0] != '.' || file.compare(file.size() - 4, 4, ".tmp") != 0) {
      continue;
    }
    const std::string_view body(file.data(), file.size() - 4);  // without ".tmp"
    long pid = -1;
    const std::size_t at = body.rfind('@');
    if (at != std::string_view::npos) {
      // ".NAME.PID-SERIAL@HOST": any target in this directory, but only this host's.
      if (body.substr(at + 1) != host) continue;
      const std::size_t dot = body.rfind('.', at);
      if (dot == std::string_view::npos || dot == 0) continue;
      pid = pid_of(body.substr(dot + 1, at - dot - 1));
    } else {
      // ".NAME.PID-SERIAL": only this target's (the name may have been cut to fit).
      const std::size_t dot = body.rfind('.');
      if (dot == std::string_view::npos || dot < 2) continue;
      const std::string_view stem = body.substr(1, dot - 1);
      if (stem.empty() || name.compare(0, stem.size(), stem) != 0) continue;
      pid = pid_of(body.substr(dot + 1));
    }
    if (pid <= 0) continue;
    struct stat info {};
    if (::lstat(it->path().c_str(), &info) != 0 || !S_ISREG(info.st_mode)) continue;
    if (!writer_gone(pid, static_cast<double>(info.st_mtime))) continue;
    if (::unlink(it->path().c_str()) == 0) removed.push_back(it->path().string());
  }
  return removed;
}

std::string output_path_problem(const std::string& path_text) {
  if (path_text.empty()) return "an output file name is required";
  const std::filesystem::path path(path_text);
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..") {
    return "the path names a directory, not a file";
  }
  const std::filesystem::path dir = directory_of(path);

  const long name_max = file_name_limit(dir.string());
  if (static_cast<long>(name.size()) > name_max) {
    return fmt::format(
        "the file name is {} bytes long; this file system allows at most {} bytes (NAME_MAX)",
        name.size(),
        name_max);
  }
  // The temporary's path, not only the target's, must fit PATH_MAX (the limit of any path handed
  // to the kernel, terminating NUL included).
  const std::size_t longest_temporary =
      path_text.size() - name.size() +
      std::min<std::size_t>(static_cast<std::size_t>(name_max), name.size() + kTemporaryOverhead);
  if (longest_temporary >= PATH_MAX) {
    return fmt::format(
        "the path is {} bytes long; with the temporary file name it would exceed the limit of {} "
        "bytes (PATH_MAX)",
        path_text.size(),
        PATH_MAX - 1);
  }

  struct stat dir_info {};
  if (::stat(dir.c_str(), &dir_info) != 0) {
    return fmt::format("directory '{}' does not exist ({})", dir.string(), std::strerror(errno));
  }
  if (!S_ISDIR(dir_info.st_mode)) return fmt::format("'{}' is not a directory", dir.string());
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    return fmt::format("directory '{}' is not writable ({})", dir.string(), std::strerror(errno));
  }

  // What the target is now. rename() replaces a file, but also a FIFO or a device node (as root,
  // --out /dev/null would replace /dev/null), and cannot replace a directory.
  struct stat target {};
  if (::stat(path.c_str(), &target) == 0) {
    if (S_ISDIR(target.st_mode)) return "the path is an existing directory";
    if (!S_ISREG(target.st_mode)) {
      return fmt::format(
          "the path exists and is {}; flexure only replaces regular files (it writes a new file "
          "and renames it over the target)",
          kind_of(target.st_mode));
    }
  }
  // In a sticky directory (such as /tmp) only the owner of an entry, the owner of the directory or
  // a process with CAP_FOWNER may replace it: rename() would fail with EPERM after all the work.
  struct stat entry {};
  if ((dir_info.st_mode & S_ISVTX) != 0 && ::lstat(path.c_str(), &entry) == 0) {
    const uid_t me = ::geteuid();
    if (entry.st_uid != me && dir_info.st_uid != me && !has_cap_fowner()) {
      return fmt::format(
          "the existing file belongs to user {} in the sticky directory '{}' (owned by user {}): "
          "only its owner can replace it; choose another name or remove the file first",
          user_name(entry.st_uid),
          dir.string(),
          user_name(dir_info.st_uid));
    }
  }
  return {};
}

void check_output_path(const std::string& path, const std::string& option) {
  const std::string problem = output_path_problem(path);
  if (!problem.empty()) {
    throw InvalidInput(
        fmt::format("{} '{}': cannot write the file there: {}", option, path, problem));
  }
}

void write_text_file(const std::string& path, const std::string& text, const std::string& option) {
  check_output_path(path, option);
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target(path);
  const std::string directory =
      target.parent_path().empty() ? std::string(".") : target.parent_path().string();
  // Temporaries of killed runs (kill -9) that no handler could remove.
  remove_stale_temporaries(path);
  const std::string temp = temporary_path_for(path,
                                              static_cast<long>(::getpid()),
                                              counter.fetch_add(1),
                                              file_name_limit(directory),
                                              temporary_host_tag());
  const int slot = register_temp_file(temp);
  const auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    std::remove(temp.c_str());
    unregister_temp_file(slot);
    throw InvalidInput(fmt::format("{} '{}': {}: {}", option, path, what, reason));
  };
  errno = 0;
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) fail("cannot create the temporary file");
    out << text;
    out.close();  // a write that fails only when the buffer goes out shows here
    if (!out) fail("cannot write the file");
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) fail("cannot rename the finished file");
  unregister_temp_file(slot);
}

}  // namespace flexure::io
