#include "gui/language.h"

#include <QCoreApplication>
#include <QDir>
#include <QLocale>

namespace klueng::gui {

namespace {
Language* g_instance = nullptr;
}

Language::Language(QObject* parent) : QObject(parent) {
  if (!g_instance) g_instance = this;
}

Language::~Language() {
  // Parented to the application, this may run after the application is gone.
  if (QCoreApplication::instance())
    for (auto& t : translators_) QCoreApplication::removeTranslator(t.get());
  if (g_instance == this) g_instance = nullptr;
}

Language* Language::instance() {
  if (!g_instance) g_instance = new Language(QCoreApplication::instance());
  return g_instance;
}

void Language::setLanguage(const QString& requested) {
  const QString code = requested == QStringLiteral("th") ? requested : QStringLiteral("en");
  if (code == code_) return;
  for (auto& t : translators_) QCoreApplication::removeTranslator(t.get());
  translators_.clear();
  code_ = code;
  if (isThai()) {
    // Every area's translation (shell, views, dialogs) ends in _th.qm.
    const QDir dir(QStringLiteral(":/i18n"));
    for (const QString& name : dir.entryList({QStringLiteral("*_th.qm")}, QDir::Files, QDir::Name)) {
      auto t = std::make_unique<QTranslator>();
      if (t->load(dir.filePath(name))) {
        QCoreApplication::installTranslator(t.get());
        translators_.push_back(std::move(t));
      }
    }
    QLocale::setDefault(QLocale(QLocale::Thai, QLocale::Thailand));
  } else {
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
  }
  // Removing the last translator sends no LanguageChange by itself on every Qt
  // version; send one so every widget retranslates either way.
  if (translators_.empty()) {
    QEvent ev(QEvent::LanguageChange);
    QCoreApplication::sendEvent(QCoreApplication::instance(), &ev);
  }
  emit languageChanged(code_);
}

core::Lang Language::coreLang() { return instance()->isThai() ? core::Lang::Th : core::Lang::En; }

}  // namespace klueng::gui
