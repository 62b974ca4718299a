// ISO 286-1/-2 limit deviations and ISO 2768-1 general tolerances, from the
// standards' tables (micrometres; sizes "over a up to and including b").
#include "klueng/core/design/iso_fits.h"

#include <array>
#include <cctype>
#include <cmath>
#include <string_view>

namespace klueng::core::design {

namespace {

// The 25 size ranges' upper ends; most tables only split at the 13 main ones.
constexpr std::array<double, 25> kFine = {3,   6,   10,  14,  18,  24,  30,  40,  50,  65,  80,  100, 120,
                                          140, 160, 180, 200, 225, 250, 280, 315, 355, 400, 450, 500};
constexpr std::array<int, 25> kMainOf = {0, 1, 2, 3, 3, 4, 4,  5,  5,  6,  6,  7, 7,
                                         8, 8, 8, 9, 9, 9, 10, 10, 11, 11, 12, 12};

// Standard tolerance grades IT1-IT18 by main range (µm).
constexpr double kIt[18][13] = {
    {0.8, 1, 1, 1.2, 1.5, 1.5, 2, 2.5, 3.5, 4.5, 6, 7, 8},
    {1.2, 1.5, 1.5, 2, 2.5, 2.5, 3, 4, 5, 7, 8, 9, 10},
    {2, 2.5, 2.5, 3, 4, 4, 5, 6, 8, 10, 12, 13, 15},
    {3, 4, 4, 5, 6, 7, 8, 10, 12, 14, 16, 18, 20},
    {4, 5, 6, 8, 9, 11, 13, 15, 18, 20, 23, 25, 27},
    {6, 8, 9, 11, 13, 16, 19, 22, 25, 29, 32, 36, 40},
    {10, 12, 15, 18, 21, 25, 30, 35, 40, 46, 52, 57, 63},
    {14, 18, 22, 27, 33, 39, 46, 54, 63, 72, 81, 89, 97},
    {25, 30, 36, 43, 52, 62, 74, 87, 100, 115, 130, 140, 155},
    {40, 48, 58, 70, 84, 100, 120, 140, 160, 185, 210, 230, 250},
    {60, 75, 90, 110, 130, 160, 190, 220, 250, 290, 320, 360, 400},
    {100, 120, 150, 180, 210, 250, 300, 350, 400, 460, 520, 570, 630},
    {140, 180, 220, 270, 330, 390, 460, 540, 630, 720, 810, 890, 970},
    {250, 300, 360, 430, 520, 620, 740, 870, 1000, 1150, 1300, 1400, 1550},
    {400, 480, 580, 700, 840, 1000, 1200, 1400, 1600, 1850, 2100, 2300, 2500},
    {600, 750, 900, 1100, 1300, 1600, 1900, 2200, 2500, 2900, 3200, 3600, 4000},
    {1000, 1200, 1500, 1800, 2100, 2500, 3000, 3500, 4000, 4600, 5200, 5700, 6300},
    {1400, 1800, 2200, 2700, 3300, 3900, 4600, 5400, 6300, 7200, 8100, 8900, 9700},
};

// Shafts' fundamental deviations (µm): upper (es) for c-h, lower (ei) for k-s.
constexpr double kC[25] = {-60,  -70,  -80,  -95,  -95,  -110, -110, -120, -130, -140, -150, -170, -180,
                           -200, -210, -230, -240, -260, -280, -300, -330, -360, -400, -440, -480};
constexpr double kD[13] = {-20, -30, -40, -50, -65, -80, -100, -120, -145, -170, -190, -210, -230};
constexpr double kE[13] = {-14, -20, -25, -32, -40, -50, -60, -72, -85, -100, -110, -125, -135};
constexpr double kF[13] = {-6, -10, -13, -16, -20, -25, -30, -36, -43, -50, -56, -62, -68};
constexpr double kG[13] = {-2, -4, -5, -6, -7, -9, -10, -12, -14, -15, -17, -18, -20};
constexpr double kK[13] = {0, 1, 1, 1, 2, 2, 2, 3, 3, 4, 4, 4, 5};  // grades 4-7; 0 otherwise
constexpr double kM[13] = {2, 4, 6, 7, 8, 9, 11, 13, 15, 17, 20, 21, 23};
constexpr double kN[13] = {4, 8, 10, 12, 15, 17, 20, 23, 27, 31, 34, 37, 40};
constexpr double kP[13] = {6, 12, 15, 18, 22, 26, 32, 37, 43, 50, 56, 62, 68};
constexpr double kR[25] = {10, 15, 19, 23, 23, 28, 28, 34, 34,  41,  43,  51, 54,
                           63, 65, 68, 77, 80, 84, 94, 98, 108, 114, 126, 132};
constexpr double kS[25] = {14, 19,  23,  28,  28,  35,  35,  43,  43,  53,  59,  71, 79,
                           92, 100, 108, 122, 130, 140, 158, 170, 190, 208, 232, 252};

struct ShaftDeviation {
  bool upper = true;  // es (c-h) or ei (k-s)
  double value = 0.0;
};

// The shaft letter's fundamental deviation at a size and grade, or nullopt for a letter not in the tables.
std::optional<ShaftDeviation> shaftDeviation(std::string_view letter, int fine, int grade) {
  const int main = kMainOf[static_cast<std::size_t>(fine)];
  if (letter == "c") return ShaftDeviation{true, kC[fine]};
  if (letter == "d") return ShaftDeviation{true, kD[main]};
  if (letter == "e") return ShaftDeviation{true, kE[main]};
  if (letter == "f") return ShaftDeviation{true, kF[main]};
  if (letter == "g") return ShaftDeviation{true, kG[main]};
  if (letter == "h") return ShaftDeviation{true, 0.0};
  if (letter == "k") return ShaftDeviation{false, grade >= 4 && grade <= 7 ? kK[main] : 0.0};
  if (letter == "m") return ShaftDeviation{false, kM[main]};
  if (letter == "n") return ShaftDeviation{false, kN[main]};
  if (letter == "p") return ShaftDeviation{false, kP[main]};
  if (letter == "r") return ShaftDeviation{false, kR[fine]};
  if (letter == "s") return ShaftDeviation{false, kS[fine]};
  return std::nullopt;
}

cut::Tolerance fromMicrons(double upper, double lower, const std::string& text) {
  return cut::Tolerance{upper / 1000.0, lower / 1000.0, text};
}

}  // namespace

std::optional<cut::Tolerance> isoFit(const std::string& toleranceClass, double size) {
  if (!(size > 0.0) || size > 500.0) return std::nullopt;
  std::size_t digits = 0;
  while (digits < toleranceClass.size() && std::isalpha(static_cast<unsigned char>(toleranceClass[digits]))) ++digits;
  const std::string letter = toleranceClass.substr(0, digits);
  const std::string gradeText = toleranceClass.substr(digits);
  if (letter.empty() || gradeText.empty() || gradeText.size() > 2 || gradeText[0] == '0') return std::nullopt;
  for (char c : gradeText)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  const int grade = std::stoi(gradeText);
  if (grade < 1 || grade > 18) return std::nullopt;
  int fine = 0;
  while (size > kFine[static_cast<std::size_t>(fine)] + 1e-9) ++fine;
  const int main = kMainOf[static_cast<std::size_t>(fine)];
  const double it = kIt[grade - 1][main];
  // All capitals a hole, all small letters a shaft ("Js" is neither).
  bool allUpper = true, allLower = true;
  for (char c : letter) {
    allUpper = allUpper && std::isupper(static_cast<unsigned char>(c));
    allLower = allLower && std::islower(static_cast<unsigned char>(c));
  }
  if (!allUpper && !allLower) return std::nullopt;
  const bool hole = allUpper;
  std::string lower = letter;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "js") return fromMicrons(it / 2.0, -it / 2.0, toleranceClass);
  const auto shaft = shaftDeviation(lower, fine, grade);
  if (!shaft) return std::nullopt;
  if (!hole) {
    if (shaft->upper) return fromMicrons(shaft->value, shaft->value - it, toleranceClass);
    return fromMicrons(shaft->value + it, shaft->value, toleranceClass);
  }
  // Holes: A-H mirror the shaft (EI = -es); K-ZC take ES = -ei, plus Δ = ITn - IT(n-1)
  // for K, M, N up to grade 8 and P-ZC up to grade 7 (ISO 286-1, table 3). No Δ up to 3 mm.
  if (shaft->upper) return fromMicrons(-shaft->value + it, -shaft->value, toleranceClass);
  const double delta = size <= 3.0 || grade < 3 ? 0.0 : it - kIt[grade - 2][main];
  double es = 0.0;
  if (lower == "k" || lower == "m" || lower == "n") {
    if (grade < 3) return std::nullopt;  // the standard has no Δ below IT3
    if (grade <= 8)
      es = -shaft->value + delta;
    else if (lower == "m" || size <= 3.0)
      es = -shaft->value;
    else
      es = 0.0;  // K and N above IT8 over 3 mm
    if (lower == "k" && grade <= 8) es = -(size <= 3.0 ? 0.0 : kK[main]) + delta;
  } else {
    if (grade < 3) return std::nullopt;
    es = -shaft->value + (grade <= 7 ? delta : 0.0);
  }
  return fromMicrons(es, es - it, toleranceClass);
}

std::optional<cut::Tolerance> generalTolerance(const std::string& toleranceClass, double size) {
  static constexpr double kUpTo[8] = {3, 6, 30, 120, 400, 1000, 2000, 4000};
  static constexpr double kTable[4][8] = {{0.05, 0.05, 0.1, 0.15, 0.2, 0.3, 0.5, -1},
                                          {0.1, 0.1, 0.2, 0.3, 0.5, 0.8, 1.2, 2},
                                          {0.2, 0.3, 0.5, 0.8, 1.2, 2, 3, 4},
                                          {-1, 0.5, 1, 1.5, 2.5, 4, 6, 8}};
  static constexpr std::string_view kClasses = "fmcv";
  if (toleranceClass.size() != 1 || kClasses.find(toleranceClass[0]) == std::string_view::npos) return std::nullopt;
  if (!(size > 0.5) || size > 4000.0) return std::nullopt;
  int range = 0;
  while (size > kUpTo[range] + 1e-9) ++range;
  const double t = kTable[kClasses.find(toleranceClass[0])][range];
  if (t < 0.0) return std::nullopt;
  return cut::Tolerance{t, -t, "ISO 2768-" + toleranceClass};
}

}  // namespace klueng::core::design
