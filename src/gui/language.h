#pragma once
// The UI language, Thai or English, switched at once everywhere: installs the
// compiled translations from :/i18n (every klueng_*_th.qm), which makes Qt send
// QEvent::LanguageChange to every widget; widgets retranslate in changeEvent().
// Texts that come from the core (diagnostics, code help) use coreLang().
#include <QObject>
#include <QString>
#include <QTranslator>
#include <memory>
#include <vector>

#include "klueng/core/messages.h"

namespace klueng::gui {

class Language : public QObject {
  Q_OBJECT
 public:
  explicit Language(QObject* parent = nullptr);
  ~Language() override;

  // The application-wide instance (created by the first constructor call).
  static Language* instance();

  // "en" or "th"; unknown codes mean English. Does nothing if already active.
  void setLanguage(const QString& code);
  QString language() const { return code_; }
  bool isThai() const { return code_ == QStringLiteral("th"); }
  void toggle() { setLanguage(isThai() ? QStringLiteral("en") : QStringLiteral("th")); }

  // The core's language for formatMessage() and the code table.
  static core::Lang coreLang();

  // Number of translation files loaded for Thai (for tests and diagnostics).
  int loadedTranslationCount() const { return static_cast<int>(translators_.size()); }

 signals:
  void languageChanged(const QString& code);

 private:
  QString code_ = QStringLiteral("en");
  std::vector<std::unique_ptr<QTranslator>> translators_;
};

}  // namespace klueng::gui
