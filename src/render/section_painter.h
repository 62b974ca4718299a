#pragma once
// The section picture (section_picture.h) drawn with the screen's painters.
// No QGuiApplication is needed: nothing here draws text.
#include <QByteArray>
#include <QImage>

#include "render/section_picture.h"

namespace klueng::render {

QImage renderSectionPicture(const SectionPicture& picture);
// PNG bytes of the picture (empty when encoding fails).
QByteArray sectionPicturePng(const SectionPicture& picture);

}  // namespace klueng::render
