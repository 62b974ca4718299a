// Starts the real `klueng` under Xvfb (xvfb-run -a) with --screenshot, then
// checks the PNG: the window's size, and a real picture, not a blank one.
#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QRect>
#include <QTest>

class ScreenshotCheck : public QObject {
  Q_OBJECT
 private slots:
  void realProgramUnderXvfb() {
    const QString out = QStringLiteral(KLUENG_SHOT_DIR "/klueng-xvfb.png");
    QFile::remove(out);
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("QT_QPA_PLATFORM"));  // the real xcb platform on Xvfb's display
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(XVFB_RUN_PATH),
            {QStringLiteral("-a"), QStringLiteral("-s"), QStringLiteral("-screen 0 1600x1000x24"),
             QStringLiteral(KLUENG_APP_PATH), QStringLiteral("--screenshot"), out,
             QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")});
    QVERIFY2(p.waitForFinished(90000), "klueng did not finish under Xvfb");
    const QString stdoutText = QString::fromLocal8Bit(p.readAllStandardOutput());
    QCOMPARE(p.exitCode(), 0);
    const QRegularExpression re(QStringLiteral("screenshot saved (\\d+)x(\\d+) window (\\d+)x(\\d+)"));
    const auto m = re.match(stdoutText);
    QVERIFY2(m.hasMatch(), qPrintable(stdoutText + QString::fromLocal8Bit(p.readAllStandardError())));
    const int windowW = m.captured(3).toInt();
    const int windowH = m.captured(4).toInt();
    QVERIFY(windowW >= 800 && windowH >= 500);

    QImage img(out);
    QVERIFY(!img.isNull());
    QCOMPARE(img.width(), windowW * static_cast<int>(img.devicePixelRatio()));
    QCOMPARE(img.height(), windowH * static_cast<int>(img.devicePixelRatio()));
    // Non-blank: many colours (text, icons, the stock) and no colour covering nearly all of it.
    QHash<QRgb, int> counts;
    for (int y = 0; y < img.height(); y += 2)
      for (int x = 0; x < img.width(); x += 2) ++counts[img.pixel(x, y)];
    int dominant = 0;
    for (int c : counts) dominant = std::max(dominant, c);
    const int samples = ((img.width() + 1) / 2) * ((img.height() + 1) / 2);
    QVERIFY2(counts.size() > 100, qPrintable(QStringLiteral("only %1 colours").arg(counts.size())));
    QVERIFY2(dominant < samples * 0.8, "one colour covers more than 80% of the window");
  }

  // Issue 11: on a 1366 x 768 classroom screen, with fresh settings, the whole
  // window (status bar included) lies on the screen, in English and in Thai.
  void fitsAClassroomScreenInBothLanguages() {
    for (const QString& lang : {QStringLiteral("en"), QStringLiteral("th")}) {
      QTemporaryDir home;
      const QString out = QStringLiteral(KLUENG_SHOT_DIR "/klueng-1366-%1.png").arg(lang);
      QFile::remove(out);
      QProcess p;
      QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
      env.remove(QStringLiteral("QT_QPA_PLATFORM"));
      env.insert(QStringLiteral("XDG_CONFIG_HOME"), home.filePath(QStringLiteral("config")));
      env.insert(QStringLiteral("XDG_DATA_HOME"), home.filePath(QStringLiteral("data")));
      p.setProcessEnvironment(env);
      p.start(QStringLiteral(XVFB_RUN_PATH),
              {QStringLiteral("-a"), QStringLiteral("-s"), QStringLiteral("-screen 0 1366x768x24"),
               QStringLiteral(KLUENG_APP_PATH), QStringLiteral("--lang"), lang, QStringLiteral("--screenshot"), out,
               QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt")});
      QVERIFY2(p.waitForFinished(90000), "klueng did not finish under Xvfb");
      const QString text = QString::fromLocal8Bit(p.readAllStandardOutput());
      QCOMPARE(p.exitCode(), 0);
      const QRegularExpression re(
          QStringLiteral("frame (-?\\d+),(-?\\d+) (\\d+)x(\\d+) screen (-?\\d+),(-?\\d+) (\\d+)x(\\d+)"));
      const auto m = re.match(text);
      QVERIFY2(m.hasMatch(), qPrintable(text));
      const QRect frame(m.captured(1).toInt(), m.captured(2).toInt(), m.captured(3).toInt(), m.captured(4).toInt());
      const QRect screen(m.captured(5).toInt(), m.captured(6).toInt(), m.captured(7).toInt(), m.captured(8).toInt());
      QCOMPARE(screen.width(), 1366);
      QVERIFY2(screen.contains(frame), qPrintable(lang + QStringLiteral(": ") + text));
      QVERIFY(!QImage(out).isNull());
    }
  }

  // Issue 42 item 2: `--screenshot X X` and a picture onto a tool bitmap of the setup
  // folder are refused (F126, exit 2) and the file keeps its bytes.
  void screenshotNeverReplacesAnInput() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString source = QStringLiteral(KLUENG_SOURCE_DIR);
    QVERIFY(QDir().mkpath(dir.filePath(QStringLiteral("resources/tools"))));
    for (const QString& f : {QStringLiteral("tools.cfg"), QStringLiteral("offset.cfg"), QStringLiteral("machine.cfg")})
      QVERIFY(QFile::copy(source + QLatin1Char('/') + f, dir.filePath(f)));
    const QDir tools(source + QStringLiteral("/resources/tools"));
    for (const QString& f : tools.entryList({QStringLiteral("*.bmp")}, QDir::Files))
      QVERIFY(QFile::copy(tools.filePath(f), dir.filePath(QStringLiteral("resources/tools/") + f)));
    const QString program = dir.filePath(QStringLiteral("prog.txt"));
    QVERIFY(QFile::copy(QStringLiteral(KLUENG_SAMPLES_DIR "/01-step-shaft.txt"), program));
    const QString bitmap = dir.filePath(QStringLiteral("resources/tools/01-outside-turning.bmp"));
    for (const QString& out : {program, bitmap}) {
      QFile before(out);
      QVERIFY(before.open(QIODevice::ReadOnly));
      const QByteArray bytes = before.readAll();
      before.close();
      QProcess p;
      QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
      env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
      env.insert(QStringLiteral("KLUENG_DATA_DIR"), dir.path());
      env.insert(QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("home/config")));
      env.insert(QStringLiteral("XDG_DATA_HOME"), dir.filePath(QStringLiteral("home/data")));
      p.setProcessEnvironment(env);
      p.start(QStringLiteral(KLUENG_APP_PATH),
              {QStringLiteral("--lang"), QStringLiteral("en"), QStringLiteral("--screenshot"), out, program});
      QVERIFY2(p.waitForFinished(90000), "klueng did not finish");
      const QString err = QString::fromLocal8Bit(p.readAllStandardError());
      QCOMPARE(p.exitCode(), 2);
      QVERIFY2(err.contains(QStringLiteral("F126")) || err.contains(QStringLiteral("this output is the input file")),
               qPrintable(err));
      QFile after(out);
      QVERIFY(after.open(QIODevice::ReadOnly));
      QCOMPARE(after.readAll(), bytes);
    }
  }
};

QTEST_GUILESS_MAIN(ScreenshotCheck)
#include "screenshot_check.moc"
