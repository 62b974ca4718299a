// klueng: the desktop CNC lathe simulator.
//   klueng [FILE]                      open FILE (a program) at start
//   klueng --lang th|en                UI language for this and later starts
//   klueng --screenshot OUT.png FILE   open, check, save a picture of the window, exit
#include <QApplication>
#include <QBuffer>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QIcon>
#include <QScreen>
#include <QTimer>
#include <cstdio>

#include "gui/document.h"
#include "gui/file_save.h"
#include "gui/job_document.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"
#include "gui/settings.h"
#include "klueng/core/io/file_write.h"

namespace {

// Grab the window once the file is loaded and checked, then quit.
void scheduleScreenshot(klueng::gui::MainWindow* window, const QString& out, int* exitCode) {
  auto* poll = new QTimer(window);
  poll->setInterval(100);
  QObject::connect(poll, &QTimer::timeout, window, [window, out, exitCode, poll] {
    if (window->isBusy()) return;
    poll->stop();
    // The program and every file of the setup are inputs: a picture never replaces one (issue 42).
    std::vector<std::string> inputs = klueng::gui::setupInputs(window->jobDocument().tools().setup);
    if (const QString file = window->document()->filePath(); !file.isEmpty()) inputs.push_back(file.toStdString());
    if (const QString why = klueng::gui::outputIsAnyInput(out, inputs); !why.isEmpty()) {
      std::fprintf(stderr, "%s\n", qPrintable(why));
      std::printf("screenshot REFUSED\n");
      std::fflush(stdout);
      *exitCode = 2;
      QApplication::exit(*exitCode);
      return;
    }
    // One more pass so the last repaint (underlines, fit to view) is done.
    QTimer::singleShot(300, window, [window, out, exitCode] {
      const QPixmap shot = window->grab();
      // Encoded in memory, written by the checked writer: a failed write keeps an old picture (issue 29).
      QBuffer png;
      png.open(QIODevice::WriteOnly);
      const bool encoded = shot.save(&png, "PNG");
      const QString why =
          encoded ? klueng::gui::writeFileChecked(
                        out, std::string_view(png.data().constData(), static_cast<std::size_t>(png.data().size())))
                  : QString();
      if (!why.isEmpty()) std::fprintf(stderr, "%s\n", qPrintable(why));
      const bool ok = encoded && why.isEmpty();
      // Where the window lies and the screen's free area, so tests can see it fits (issue 11).
      const QRect frame = window->frameGeometry();
      const QRect screen = window->screen() ? window->screen()->availableGeometry() : QRect();
      std::printf("screenshot %s %dx%d window %dx%d frame %d,%d %dx%d screen %d,%d %dx%d\n", ok ? "saved" : "FAILED",
                  shot.width(), shot.height(), window->width(), window->height(), frame.x(), frame.y(), frame.width(),
                  frame.height(), screen.x(), screen.y(), screen.width(), screen.height());
      std::fflush(stdout);
      *exitCode = ok ? 0 : 1;
      QApplication::exit(*exitCode);
    });
  });
  poll->start();
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  // A kill during a save leaves no temporary file beside the program (issue 42).
  klueng::core::io::removeTemporaryFilesOnSignals();
  QApplication::setOrganizationName(QStringLiteral("Klueng"));
  QApplication::setApplicationName(QStringLiteral("klueng"));
  QApplication::setApplicationDisplayName(QStringLiteral("Klueng"));
  QApplication::setApplicationVersion(QStringLiteral(KLUENG_VERSION));
  klueng::gui::initResources();
  QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/klueng.svg")));

  QCommandLineParser parser;
  parser.setApplicationDescription(QStringLiteral("Klueng CNC lathe simulator"));
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption langOption(QStringLiteral("lang"), QStringLiteral("UI language: th or en."),
                                      QStringLiteral("code"));
  const QCommandLineOption shotOption(QStringLiteral("screenshot"),
                                      QStringLiteral("Save a PNG of the window to FILE and exit."),
                                      QStringLiteral("FILE"));
  parser.addOption(langOption);
  parser.addOption(shotOption);
  parser.addPositionalArgument(QStringLiteral("program"), QStringLiteral("The program file to open."));
  parser.process(app);

  if (parser.isSet(langOption)) klueng::gui::Settings().setLanguage(parser.value(langOption));

  klueng::gui::MainWindow window;
  window.show();
  const QStringList files = parser.positionalArguments();
  if (!files.isEmpty()) window.openFile(QFileInfo(files.first()).absoluteFilePath());

  int screenshotExit = 0;
  if (parser.isSet(shotOption)) scheduleScreenshot(&window, parser.value(shotOption), &screenshotExit);
  const int rc = QApplication::exec();
  return parser.isSet(shotOption) ? screenshotExit : rc;
}
