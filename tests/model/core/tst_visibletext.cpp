// Text from a workspace reaches terminals, logs and reports with its control characters made
// visible: every C0 and C1 control, DEL and the Unicode line separators.
#include "core/visibletext.h"

#include <QtTest>

using namespace rosarch;

class TestVisibleText : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void everyControlCharacterIsEscaped()
    {
        for (char16_t c = 0; c < 0x2100; ++c) {
            const bool control = c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0x2028 || c == 0x2029;
            const QString text = QStringLiteral("a") + QChar(c) + QStringLiteral("b");
            const QString shown = visibleText(text);
            QCOMPARE(isHiddenControl(c), control);
            if (!control) {
                QCOMPARE(shown, text);
                continue;
            }
            for (QChar s : shown)
                QVERIFY2(!isHiddenControl(s.unicode()), qPrintable(shown));
            QVERIFY(shown.startsWith(QLatin1String("a\\")) && shown.endsWith(QLatin1Char('b')));
        }
        QCOMPARE(visibleText(QStringLiteral("red\x1b[31m\x07")),
                 QStringLiteral("red\\x1b[31m\\x07"));
        QCOMPARE(visibleText(QString(QChar(0x9b)) + QStringLiteral("2J")),
                 QStringLiteral("\\x9b2J"));
        QCOMPARE(visibleText(QString(QChar(0x2028))), QStringLiteral("\\u2028"));
    }

    void newlinesStayOnlyWhenAsked()
    {
        const QString text = QStringLiteral("a\nb\tc\rd");
        QCOMPARE(visibleText(text), QStringLiteral("a\\x0ab\\x09c\\x0dd"));
        QCOMPARE(visibleText(text, Newlines::Keep), QStringLiteral("a\nb\tc\\x0dd"));
    }

    void fileStemsHoldNoControlOrSlash()
    {
        QCOMPARE(fileStemOf(QStringLiteral("red\x1b[31mbell\x07")),
                 QStringLiteral("red_[31mbell_"));
        QCOMPARE(fileStemOf(QStringLiteral("a/b\nc")), QStringLiteral("a_b_c"));
        QCOMPARE(fileStemOf(QStringLiteral("plain.launch")), QStringLiteral("plain.launch"));
    }
};

QTEST_GUILESS_MAIN(TestVisibleText)
#include "tst_visibletext.moc"
