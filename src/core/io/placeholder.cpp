// File formats live here (issue 2).
namespace klueng::core::io {}
