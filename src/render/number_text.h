#pragma once
// Numbers as drawings and program sheets write them: "30", "22.5", "-0.25"
// (trailing zeros and a bare point dropped, never "-0").
#include <QString>

namespace klueng::render {

inline QString trimmedNumber(double v, int decimals = 3) {
  QString s = QString::number(v, 'f', decimals);
  if (s.contains(QLatin1Char('.'))) {
    while (s.endsWith(QLatin1Char('0'))) s.chop(1);
    if (s.endsWith(QLatin1Char('.'))) s.chop(1);
  }
  return s == QStringLiteral("-0") ? QStringLiteral("0") : s;
}

}  // namespace klueng::render
