#include "gui/setup_save.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryFile>

#include "gui/file_save.h"
#include "klueng/core/io/file_write.h"

namespace klueng::gui {

namespace io = core::io;

bool setupFolderWritable(const QString& dir) {
  // Tried, not asked: access() (behind QFileInfo::isWritable) answers for the real user, and
  // root or a read-only mount would be told "writable" where the save then fails. A file
  // without write permission is the owner's "keep this", even for root (issue 29 item 2).
  if (!QFileInfo(dir).isDir()) return false;
  QTemporaryFile probe(QDir(dir).filePath(QStringLiteral(".klueng-write-test-XXXXXX")));
  if (!probe.open()) return false;
  for (const char* name : {"tools.cfg", "offset.cfg"}) {
    const QString path = QDir(dir).filePath(QString::fromLatin1(name));
    if (!QFileInfo::exists(path)) continue;
    QFile f(path);
    if (io::isReadOnlyFile(path.toStdString()) || !f.open(QIODevice::ReadWrite | QIODevice::Append)) return false;
  }
  return true;
}

QString saveSetupFiles(QWidget* parent, const SetupToSave& setup) {
  if (!setup.toolsEdited && !setup.offsetsEdited) return setup.dir;
  QString target = setup.dir;
  if (!setupFolderWritable(setup.dir)) {
    QMessageBox box(parent);
    box.setObjectName(QStringLiteral("readOnlySetupBox"));
    box.setIcon(QMessageBox::Warning);
    box.setWindowTitle(QCoreApplication::translate("klueng::gui::SetupSave", "Read-only setup"));
    box.setText(QCoreApplication::translate("klueng::gui::SetupSave",
                                            "The setup in \"%1\" is read-only, so Klueng will not write over it.")
                    .arg(QDir::toNativeSeparators(setup.dir)));
    box.setInformativeText(QCoreApplication::translate(
        "klueng::gui::SetupSave", "Save the tool and offset tables to your own setup folder instead?"));
    QPushButton* own = box.addButton(QCoreApplication::translate("klueng::gui::SetupSave", "Save to &My Setup Folder"),
                                     QMessageBox::AcceptRole);
    own->setObjectName(QStringLiteral("ownFolderButton"));
    box.addButton(QCoreApplication::translate("klueng::gui::SetupSave", "Cancel"), QMessageBox::RejectRole)
        ->setObjectName(QStringLiteral("cancelButton"));
    box.setDefaultButton(own);
    box.exec();
    if (box.clickedButton() != own) return {};
    std::string error;
    target = QString::fromStdString(io::ensureUserConfigDir(&error));
    if (target.isEmpty() || !setupFolderWritable(target)) {
      QMessageBox::warning(
          parent, QCoreApplication::translate("klueng::gui::SetupSave", "Cannot save the setup"),
          QCoreApplication::translate("klueng::gui::SetupSave", "Cannot save the setup: %1")
              .arg(target.isEmpty() ? QString::fromStdString(error) : QDir::toNativeSeparators(target)));
      return {};
    }
  }
  const bool elsewhere = QDir(target) != QDir(setup.dir);
  // In another folder both tables go there: it becomes the setup that is read.
  if (setup.toolsEdited || elsewhere) {
    io::ToolTable out = *setup.tools;
    if (elsewhere) {
      // Names relative to the old folder must still find their bitmaps.
      for (std::size_t i = 0; i < out.bitmap.size(); ++i) {
        const QString q = QString::fromStdString(out.bitmap[i]);
        if (q.isEmpty() || q.startsWith(QLatin1String(io::kLibraryPrefix.data())) || QFileInfo(q).isAbsolute() ||
            QFileInfo::exists(QDir(target).filePath(q)))
          continue;
        out.bitmap[i] = QFileInfo(QDir(setup.dir).filePath(q)).absoluteFilePath().toStdString();
      }
    }
    out.folder = target.toStdString();
    if (const QString why =
            writeFileChecked(QDir(target).filePath(QStringLiteral("tools.cfg")), io::formatToolTable(out));
        !why.isEmpty()) {
      QMessageBox::warning(
          parent, QCoreApplication::translate("klueng::gui::SetupSave", "Cannot save the setup"),
          QCoreApplication::translate("klueng::gui::SetupSave", "Cannot save the tool table: %1").arg(why));
      return {};
    }
  }
  if (setup.offsetsEdited || elsewhere) {
    if (const QString why = writeFileChecked(QDir(target).filePath(QStringLiteral("offset.cfg")),
                                             io::formatOffsetTable(*setup.offsets));
        !why.isEmpty()) {
      QMessageBox::warning(
          parent, QCoreApplication::translate("klueng::gui::SetupSave", "Cannot save the setup"),
          QCoreApplication::translate("klueng::gui::SetupSave", "Cannot save the offset table: %1").arg(why));
      return {};
    }
  }
  return target;
}

}  // namespace klueng::gui
