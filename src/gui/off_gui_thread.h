#pragma once
// Work that compiles or cuts (a Job's timeline, its cut, a part check) runs on
// a worker thread, never on the GUI thread (docs/architecture.md, issue 30).
// A caller that needs the answer before going on waits here. It waits without
// running events: a timer or a repaint firing inside the wait could start the
// same work again or open a dialog half-way (a nested event loop). The task
// gets a thread of its own (std::async), so it can never be run by the waiting
// thread itself, as QFuture::waitForFinished may do with a pool task that has
// not started.
#include <future>
#include <utility>

namespace klueng::gui {

template <class F>
auto offGuiThread(F&& work) {
  return std::async(std::launch::async, std::forward<F>(work)).get();
}

}  // namespace klueng::gui
