#include "app/aboutdialog.h"
#include "app/mainwindow.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"

#include <Qsci/qsciglobal.h>
#include <Qsci/qscilexer.h>
#include <Qsci/qscilexerpython.h>
#include <Qsci/qsciscintilla.h>
#include <tree_sitter/api.h>

#include <QApplication>
#include <QLabel>
#include <QSettings>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::gui;
using rosarch::test::saveScreenshot;

/// How the application looks: a dark palette followed live, the About box.
class TestAppearance : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
    }

    void followsADarkPalette()
    {
        const QPalette light = QApplication::palette();
        QPalette dark;
        dark.setColor(QPalette::Window, QColor(0x2d, 0x2d, 0x30));
        dark.setColor(QPalette::WindowText, QColor(0xdc, 0xdc, 0xdc));
        dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
        dark.setColor(QPalette::AlternateBase, QColor(0x26, 0x26, 0x28));
        dark.setColor(QPalette::Text, QColor(0xdc, 0xdc, 0xdc));
        dark.setColor(QPalette::Button, QColor(0x33, 0x33, 0x37));
        dark.setColor(QPalette::ButtonText, QColor(0xdc, 0xdc, 0xdc));
        dark.setColor(QPalette::Highlight, QColor(0x26, 0x4f, 0x78));
        dark.setColor(QPalette::HighlightedText, Qt::white);
        dark.setColor(QPalette::PlaceholderText, QColor(0x8a, 0x8a, 0x8a));
        dark.setColor(QPalette::Disabled, QPalette::Text, QColor(0x80, 0x80, 0x80));

        MainWindow w;
        w.resize(1400, 900);
        w.show();
        test::child<Document>(w)->setRecovery(handBuiltRecovery());
        test::child<AtomicNodePanel>(w)->selectSourceIndex(
            test::child<AtomicNodeModel>(w)->portIndex(QStringLiteral("arc_2"),
                                                       QStringLiteral("p1")));
        QsciScintilla *editor = test::child<SourceView>(w)->editor();
        QVERIFY(editor->lexer()->paper(0).lightnessF() > 0.5);

        // the system switches to dark while the window is open
        QApplication::setPalette(dark);
        const auto restore = qScopeGuard([&] { QApplication::setPalette(light); });
        QsciLexer *lexer = editor->lexer();
        QTRY_COMPARE(lexer->paper(0), dark.color(QPalette::Base)); // palette changes are posted
        QCOMPARE(lexer->defaultPaper(), dark.color(QPalette::Base));
        for (int style = 0; style < 128; ++style) {
            if (lexer->description(style).isEmpty())
                continue;
            QVERIFY2(lexer->color(style).lightnessF() >= 0.55,
                     qPrintable(lexer->description(style) + QStringLiteral(" is too dark: ") +
                                lexer->color(style).name()));
            QCOMPARE(lexer->paper(style), dark.color(QPalette::Base));
        }
        const QColor margin(int(editor->SendScintilla(QsciScintilla::SCI_STYLEGETBACK,
                                                      QsciScintilla::STYLE_LINENUMBER)) &
                            0xffffff);
        // Scintilla stores colours as 0xBBGGRR; darkness does not care about the order.
        QVERIFY2(qGray(margin.blue(), margin.green(), margin.red()) < 100,
                 qPrintable(margin.name()));
        saveScreenshot(w, QStringLiteral("mainwindow_dark.png"));

        // a launch file in XML follows the dark palette too
        test::child<LaunchTreePanel>(w)->selectSourceIndex(
            test::child<LaunchTreeModel>(w)->nodeIndex(QStringLiteral("n2")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListenerLaunch);
        QsciLexer *xml = editor->lexer();
        QCOMPARE(QString::fromLatin1(xml->language()), QStringLiteral("XML"));
        QCOMPARE(xml->paper(0), dark.color(QPalette::Base));
        for (int style = 0; style < 128; ++style)
            if (!xml->description(style).isEmpty())
                QVERIFY2(xml->color(style).lightnessF() >= 0.55,
                         qPrintable(xml->description(style) + QStringLiteral(" is too dark")));
        saveScreenshot(w, QStringLiteral("mainwindow_dark_launch.png"));
        test::child<AtomicNodePanel>(w)->selectSourceIndex(
            test::child<AtomicNodeModel>(w)->portIndex(QStringLiteral("arc_2"),
                                                       QStringLiteral("p1")));

        // and back to light: the keywords are dark again
        QApplication::setPalette(light);
        QTRY_COMPARE(lexer->paper(0), light.color(QPalette::Base));
        QVERIFY(lexer->color(QsciLexerPython::Keyword).lightnessF() < 0.5);
    }

    void aboutShowsVersions()
    {
        const QString html = AboutDialog::versionsHtml();
        QVERIFY(html.contains(QString::fromLatin1(qVersion())));
        QVERIFY(html.contains(QStringLiteral(QSCINTILLA_VERSION_STR)));
        QVERIFY(html.contains(QString::number(TREE_SITTER_LANGUAGE_VERSION)));
        QVERIFY(html.contains(QStringLiteral(ROSARCH_VERSION)));
        AboutDialog dialog;
        dialog.show();
        QVERIFY(dialog.findChild<QLabel *>(QString(), Qt::FindDirectChildrenOnly));
        saveScreenshot(dialog, QStringLiteral("about.png"));
    }
};

QTEST_MAIN(TestAppearance)
#include "tst_appearance.moc"
