#pragma once
// The printed sheets' language and their own words (issue 30 item 5): every
// heading, note, date and duration on a sheet comes from the core's catalog
// (src/core/base/messages_render.cpp), never from a literal in a painter.
#include <QString>
#include <QStringList>

namespace klueng::render {

enum class ReportLanguage { English, Thai };

// A sheet's words (codes::kReport*, or a kCli* text the CLI prints too) in `lang`,
// {0}.. filled from `args`.
QString reportText(const char* code, ReportLanguage lang, const QStringList& args = {});

}  // namespace klueng::render
