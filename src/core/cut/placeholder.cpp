// Material removal lives here (issue 4).
namespace klueng::core::cut {}
