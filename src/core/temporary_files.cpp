#include "lbmshape/core/temporary_files.hpp"

#include <array>
#include <atomic>
#include <climits>
#include <cstring>

#include <time.h>
#include <unistd.h>

namespace lbmshape::temporary_files {
namespace {

// A fixed table, as a signal handler may not allocate. A morph writes at
// most a few files at once (a frame, morph.glb), jobs one at a time.
struct Slot {
  std::atomic<bool> taken{false};
  // A sequence lock between writers and the handler, which may run on any
  // thread while others go on: odd while `path` holds a listed file and is
  // not changing, so the handler unlinks only a path it read whole.
  std::atomic<unsigned> sequence{0};
  char path[PATH_MAX];
};
std::array<Slot, 32> slots;

// Sequentially consistent, like Dekker's flags: either a Creation sees
// `ending` and stops, or the handler sees it in `creating` and waits for it.
std::atomic<bool> ending{false};
std::atomic<int> creating{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

}  // namespace

Creation::Creation()
{
  creating.fetch_add(1);
  if (!ending.load()) return;
  creating.fetch_sub(1);
  for (;;) ::pause();  // the handler is removing the files and ends the process
}

Creation::~Creation() { creating.fetch_sub(1); }

int remember(const std::filesystem::path& path)
{
  const std::string& text = path.native();
  if (text.size() >= PATH_MAX) return -1;
  for (size_t i = 0; i < slots.size(); ++i) {
    bool expected = false;
    if (!slots[i].taken.compare_exchange_strong(expected, true)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].sequence.fetch_add(1, std::memory_order_release);  // odd: listed
    return int(i);
  }
  return -1;
}

void forget(int ticket)
{
  if (ticket < 0) return;
  Slot& slot = slots[size_t(ticket)];
  slot.sequence.fetch_add(1, std::memory_order_release);  // even: not listed
  slot.taken.store(false, std::memory_order_release);
}

namespace {

double secondsNow()
{
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// Bounded: the handler may be running on a thread that is itself inside a
// Creation, which then never ends; its file, if made, is listed already.
void waitForCreationsUnderWay()
{
  const double deadline = secondsNow() + 0.25;
  while (creating.load() > 0 && secondsNow() < deadline) {}
}

void removeListed()
{
  for (Slot& slot : slots) {
    const unsigned before = slot.sequence.load(std::memory_order_acquire);
    if (before % 2 == 0) continue;
    char path[PATH_MAX];
    std::memcpy(path, slot.path, sizeof path);
    std::atomic_thread_fence(std::memory_order_acquire);
    if (slot.sequence.load(std::memory_order_relaxed) != before) continue;  // changed while read
    path[PATH_MAX - 1] = '\0';
    // Already renamed or removed: no matter, temporary names are never
    // reused. A folder is not a file: rmdir removes it only when empty.
    if (::unlink(path) != 0) ::rmdir(path);
  }
}

}  // namespace

void removeAllFromSignalHandler()
{
  ending.store(true);
  waitForCreationsUnderWay();
  // Twice: a listed folder may hold another listed folder of a later slot,
  // empty only once that one is gone.
  removeListed();
  removeListed();
}

}  // namespace lbmshape::temporary_files
