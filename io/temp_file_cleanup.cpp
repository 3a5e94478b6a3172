#include "flexure/io/temp_file_cleanup.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

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

extern "C" void remove_temp_files_and_reraise(int signal_number) {
  for (Slot& s : slots) {
    if (s.used.load(std::memory_order_acquire)) ::unlink(s.path);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
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

void unregister_temp_file(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  std::lock_guard<std::mutex> lock(registry_mutex);
  slots[slot].used.store(false, std::memory_order_release);
}

}  // namespace flexure::io
