#include "widgets/diagram/diagramstyle.h"
#include "core/composition.h"

#include <QPalette>

namespace rosarch {

QColor DiagramStyle::edgeColor(int category) const
{
    switch (Connection::Kind(category)) {
    case Connection::Kind::Publish:
        return dark ? QColor(0x66, 0xbb, 0x6a) : QColor(0x2e, 0x7d, 0x32);
    case Connection::Kind::Subscribe:
        return dark ? QColor(0x64, 0xb5, 0xf6) : QColor(0x15, 0x65, 0xc0);
    case Connection::Kind::Client:
        return dark ? QColor(0xef, 0x6c, 0x6c) : QColor(0xc6, 0x28, 0x28);
    case Connection::Kind::Server:
        return dark ? QColor(0xc5, 0x8a, 0xe0) : QColor(0x7b, 0x1f, 0xa2);
    case Connection::Kind::DelegationIn:
    case Connection::Kind::DelegationOut:
        return dark ? QColor(0x9e, 0x9e, 0x9e) : QColor(0x75, 0x75, 0x75);
    }
    return text;
}

DiagramStyle DiagramStyle::make(bool dark)
{
    DiagramStyle s;
    s.dark = dark;
    if (!dark) {
        s.paper = Qt::white;
        s.text = QColor(0x21, 0x21, 0x21);
        s.mutedText = QColor(0x61, 0x61, 0x61);
        s.frame = QColor(0x45, 0x5a, 0x64);
        s.frameFill = QColor(0xfb, 0xfb, 0xfc);
        s.partFill = QColor(0xe8, 0xf0, 0xfe);
        s.launchFill = QColor(0xfd, 0xf3, 0xe1);
        s.partBorder = QColor(0x3c, 0x4a, 0x5e);
        s.clusterFill = QColor(0xf1, 0xf3, 0xf5);
        s.clusterBorder = QColor(0x9a, 0xa5, 0xb1);
        s.topicFill = QColor(0xe7, 0xf5, 0xe8);
        s.serviceFill = QColor(0xf6, 0xea, 0xf8);
        s.actionFill = QColor(0xfc, 0xe9, 0xe7);
        s.boundaryFill = QColor(0xff, 0xff, 0xff);
        s.portFill = QColor(0xff, 0xff, 0xff);
        s.selection = QColor(0x19, 0x76, 0xd2);
        s.match = QColor(0xff, 0xa0, 0x00);
        s.extra = QColor(0xd3, 0x2f, 0x2f);
        s.corrected = QColor(0x00, 0x83, 0x8f);
    } else {
        s.paper = QColor(0x1e, 0x1f, 0x22);
        s.text = QColor(0xe6, 0xe6, 0xe6);
        s.mutedText = QColor(0xa8, 0xab, 0xb0);
        s.frame = QColor(0x90, 0xa4, 0xae);
        s.frameFill = QColor(0x25, 0x27, 0x2b);
        s.partFill = QColor(0x27, 0x35, 0x4a);
        s.launchFill = QColor(0x45, 0x3a, 0x22);
        s.partBorder = QColor(0x9f, 0xb3, 0xc8);
        s.clusterFill = QColor(0x2c, 0x2f, 0x34);
        s.clusterBorder = QColor(0x6b, 0x75, 0x80);
        s.topicFill = QColor(0x23, 0x3d, 0x28);
        s.serviceFill = QColor(0x3d, 0x2a, 0x44);
        s.actionFill = QColor(0x48, 0x2a, 0x27);
        s.boundaryFill = QColor(0x2b, 0x2d, 0x31);
        s.portFill = QColor(0x1e, 0x1f, 0x22);
        s.selection = QColor(0x64, 0xb5, 0xf6);
        s.match = QColor(0xff, 0xb3, 0x00);
        s.extra = QColor(0xff, 0x6b, 0x6b);
        s.corrected = QColor(0x4d, 0xd0, 0xe1);
    }
    // Pixel sizes: the scene is in points, and the layout reserved room for these metrics.
    s.titleFont = QFont(QStringLiteral("Sans Serif"));
    s.titleFont.setPixelSize(13);
    s.titleFont.setBold(true);
    s.textFont = QFont(QStringLiteral("Sans Serif"));
    s.textFont.setPixelSize(12);
    s.smallFont = QFont(QStringLiteral("Sans Serif"));
    s.smallFont.setPixelSize(11);
    return s;
}

DiagramStyle DiagramStyle::fromPalette(const QPalette &palette)
{
    return make(palette.color(QPalette::Window).lightnessF() < 0.5);
}

} // namespace rosarch
