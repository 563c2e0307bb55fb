#include "gui/background_worker.h"

#include <algorithm>

namespace ll::gui {

BackgroundWorker::BackgroundWorker() : thread_([this] { loop(); }) {}

BackgroundWorker::~BackgroundWorker() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    queue_.clear();
  }
  wake_.notify_all();
  thread_.join();
}

void BackgroundWorker::post(const std::string& slot, std::function<void()> job) {
  posted_.fetch_add(1, std::memory_order_relaxed);
  {
    std::lock_guard lock(mutex_);
    const auto it =
        std::find_if(queue_.begin(), queue_.end(), [&](const auto& q) { return q.first == slot; });
    if (it != queue_.end())
      it->second = std::move(job);
    else
      queue_.emplace_back(slot, std::move(job));
  }
  wake_.notify_all();
}

void BackgroundWorker::drain() {
  std::unique_lock lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && !running_; });
}

void BackgroundWorker::loop() {
  for (;;) {
    std::function<void()> job;
    {
      std::unique_lock lock(mutex_);
      running_ = false;
      idle_.notify_all();
      wake_.wait(lock, [this] { return quit_ || !queue_.empty(); });
      if (quit_) return;
      job = std::move(queue_.front().second);
      queue_.pop_front();
      running_ = true;
    }
    job();  // jobs catch their own errors: they report into their mailbox
  }
}

}  // namespace ll::gui
