// Painters shared by screen, print and export (issue 5).
namespace klueng::render {}
