#pragma once
// The icons and samples compiled into the static klueng_gui library must be
// registered once by any program that links it (the app and the GUI tests).
namespace klueng::gui {
void initResources();
}
