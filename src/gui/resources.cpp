#include "gui/resources.h"

#include <QtGlobal>

// Q_INIT_RESOURCE declares an extern function, so it must run at global scope.
static void initKluengResources() { Q_INIT_RESOURCE(klueng); }

namespace klueng::gui {
void initResources() { ::initKluengResources(); }
}  // namespace klueng::gui
