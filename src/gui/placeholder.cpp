// Widgets (issue 5).
namespace klueng::gui {}
