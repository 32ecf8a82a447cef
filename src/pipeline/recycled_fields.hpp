// Fields for a morph's frames, used again once the frame writer lets them
// go. A new field of 64 MB (256^3) has every page faulted in and cleared by
// one thread: on an H100's host that took longer than the device's steps
// and read-back of the frame together.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

namespace lbmshape {

template <class Field>
class RecycledFields {
public:
  // An idle field (holding the last values it was given) or a new, empty
  // one. When the last owner lets it go, on whatever thread, it goes back
  // on the shelf, or is freed where the shelf already holds `kKept`.
  std::shared_ptr<Field> take()
  {
    std::unique_ptr<Field> field;
    {
      const std::lock_guard lock(shelf_->mutex);
      if (!shelf_->idle.empty()) {
        field = std::move(shelf_->idle.back());
        shelf_->idle.pop_back();
      }
    }
    if (!field) field = std::make_unique<Field>();
    return std::shared_ptr<Field>(field.release(), [shelf = shelf_](Field* returned) {
      std::unique_ptr<Field> back(returned);
      const std::lock_guard lock(shelf->mutex);
      if (shelf->idle.size() < kKept) shelf->idle.push_back(std::move(back));
    });
  }

private:
  // The frames in flight (the one the lattice holds, two queued, one being
  // written) come back one at a time: two idle fields are enough for the
  // next, and no more stay allocated after the last frame.
  static constexpr size_t kKept = 2;
  struct Shelf {
    std::mutex mutex;
    std::vector<std::unique_ptr<Field>> idle;
  };
  std::shared_ptr<Shelf> shelf_ = std::make_shared<Shelf>();
};

}  // namespace lbmshape
