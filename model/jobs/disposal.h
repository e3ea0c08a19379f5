#pragma once

#include "core/threadpriority.h"

#include <QThreadPool>

#include <memory>
#include <type_traits>
#include <utility>

namespace rosarch {

/// Destroys `value` on a thread of its own instead of here: freeing a large model (hundreds of
/// thousands of strings) costs the UI thread tens of milliseconds. Not on the global pool,
/// which Qt's painting waits for.
template <typename T> void disposeInBackground(T &&value)
{
    static QThreadPool pool; // waits for what is left when the process ends
    pool.setMaxThreadCount(1);
    auto holder = std::make_shared<std::decay_t<T>>(std::forward<T>(value));
    pool.start([holder = std::move(holder)]() mutable {
        lowerThisThreadPriority(BackgroundPriority::YieldToUi); // the pool's own thread
        holder.reset();
    });
}

} // namespace rosarch
