// One background thread for the UI's heavy but small jobs (sRGB encoding of
// pane images, the difference heatmap, error metrics), so the UI thread only
// uploads finished bytes. Jobs are keyed by a slot: posting to a slot whose
// previous job has not started yet replaces it (only the newest matters).
// Not a oneTBB task on purpose: a UI-side thread inside the render arena
// could pick up a render tile and stall a frame.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace ll::gui {

class BackgroundWorker {
 public:
  BackgroundWorker();
  ~BackgroundWorker();  // finishes the running job, drops queued ones, joins
  BackgroundWorker(const BackgroundWorker&) = delete;
  BackgroundWorker& operator=(const BackgroundWorker&) = delete;

  void post(const std::string& slot, std::function<void()> job);
  // Blocks until every posted job has run (tests and screenshots).
  void drain();
  // Jobs posted so far: a screenshot waits until a drained frame posted none.
  uint64_t posted() const { return posted_.load(std::memory_order_relaxed); }

 private:
  void loop();
  std::mutex mutex_;
  std::condition_variable wake_, idle_;
  std::deque<std::pair<std::string, std::function<void()>>> queue_;
  bool running_ = false, quit_ = false;
  std::atomic<uint64_t> posted_{0};
  std::thread thread_;
};

// A value handed from a background job to the UI thread.
template <class T>
class Mailbox {
 public:
  void put(T value) {
    std::lock_guard lock(mutex_);
    value_ = std::move(value);
  }
  std::optional<T> take() {
    std::lock_guard lock(mutex_);
    std::optional<T> v = std::move(value_);
    value_.reset();
    return v;
  }

 private:
  std::mutex mutex_;
  std::optional<T> value_;
};

}  // namespace ll::gui
