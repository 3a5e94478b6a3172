#include "flexure/io/platform/temp_file_cleanup.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

#include "flexure/io/platform/work_distribution.h"

namespace flexure::io {
namespace {

// A handful of files are open at once (one --out file, a bench checkpoint); paths up to PATH_MAX.
constexpr int kSlots = 16;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<bool> used{false};
  char path[kMaxPath] = {};
};
std::array<Slot, kSlots> slots;
std::mutex registry_mutex;  // registration only; the handler reads the atomics

constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

// set_interrupt_note: fixed buffers, published by the atomic flag (the handler reads only those).
constexpr std::size_t kMaxNote = 8192;
struct Note {
  std::atomic<bool> set{false};
  char text[kMaxNote] = {};
  char if_missing[kMaxNote] = {};
  char file[kMaxPath] = {};
};
Note note;

void write_all(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

extern "C" void remove_temp_files_and_reraise(int signal_number) {
  for (Slot& s : slots) {
    if (s.used.load(std::memory_order_acquire)) ::unlink(s.path);
  }
  // An MPI run stopped by mpirun (a rank failed, or Ctrl-C): what rank 0 had handed out.
  parallel::write_blocks_in_progress(STDERR_FILENO);
  if (note.set.load(std::memory_order_acquire)) {
    const bool missing = note.file[0] != '\0' && ::access(note.file, F_OK) != 0;
    write_all(missing ? note.if_missing : note.text);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

void copy_cut(char* to, std::size_t size, const std::string& from) {
  const std::size_t n = std::min(from.size(), size - 1);
  std::memcpy(to, from.data(), n);
  to[n] = '\0';
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : kSignals) {
      struct sigaction action = {};
      action.sa_handler = remove_temp_files_and_reraise;
      sigemptyset(&action.sa_mask);
      struct sigaction previous = {};
      // Leave a signal alone if the caller has set it to be ignored (e.g. nohup's SIGHUP).
      if (sigaction(sig, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
      sigaction(sig, &action, nullptr);
    }
  });
}

}  // namespace

int register_temp_file(const std::string& path) {
  if (path.size() >= kMaxPath) return -1;
  install_handlers_once();
  std::lock_guard<std::mutex> lock(registry_mutex);
  for (int i = 0; i < kSlots; ++i) {
    Slot& s = slots[i];
    if (s.used.load(std::memory_order_relaxed)) continue;
    std::memcpy(s.path, path.c_str(), path.size() + 1);
    s.used.store(true, std::memory_order_release);
    return i;
  }
  return -1;
}

void set_interrupt_note(const std::string& text,
                        const std::string& file,
                        const std::string& note_if_missing) {
  install_handlers_once();
  std::lock_guard<std::mutex> lock(registry_mutex);
  note.set.store(false, std::memory_order_release);
  if (text.empty()) return;
  copy_cut(note.text, kMaxNote, text);
  copy_cut(note.if_missing, kMaxNote, note_if_missing);
  copy_cut(note.file, kMaxPath, file.size() < kMaxPath ? file : std::string());
  note.set.store(true, std::memory_order_release);
}

void install_interrupt_handlers() { install_handlers_once(); }

void remove_temp_files() {
  std::lock_guard<std::mutex> lock(registry_mutex);
  for (Slot& s : slots) {
    if (s.used.load(std::memory_order_acquire)) ::unlink(s.path);
    s.used.store(false, std::memory_order_release);
  }
}

void unregister_temp_file(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  std::lock_guard<std::mutex> lock(registry_mutex);
  slots[slot].used.store(false, std::memory_order_release);
}

}  // namespace flexure::io
