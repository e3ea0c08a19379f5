// FlowLayout: a bar of widgets wraps into rows when narrow, so that a dock holding it (the
// Log's filter bar) does not make the window wider than the screen.
#include "document/document.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/flowlayout.h"

#include <QLineEdit>
#include <QPushButton>
#include <QtTest>

using namespace rosarch;

class TestFlowLayout : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void wrapsIntoRowsWhenNarrow()
    {
        QWidget bar;
        auto *layout = new FlowLayout(&bar);
        QList<QPushButton *> buttons;
        for (int i = 0; i < 6; ++i) {
            buttons.append(new QPushButton(QStringLiteral("Button number %1").arg(i), &bar));
            layout->addWidget(buttons.last());
        }
        auto *search = new QLineEdit(&bar);
        layout->addWidget(search);
        layout->setStretchWidget(search);
        const int widest = buttons.first()->sizeHint().width();
        // as narrow as its widest widget, never as the sum of them
        QVERIFY(layout->minimumSize().width() < 2 * widest);
        QVERIFY(layout->sizeHint().width() >= 6 * widest);

        const int oneRow = layout->heightForWidth(layout->sizeHint().width());
        const int narrow = layout->heightForWidth(widest + 2 * widest / 3);
        QVERIFY2(narrow >= 6 * buttons.first()->sizeHint().height(),
                 qPrintable(QString::number(narrow))); // one button per row, and the search
        QVERIFY(oneRow < narrow);

        // laid out wide: one row, the search field takes what is left of it
        bar.resize(layout->sizeHint().width() + 300, oneRow);
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        for (QPushButton *b : std::as_const(buttons))
            QCOMPARE(b->y(), buttons.first()->y());
        QVERIFY(search->width() >= search->sizeHint().width() + 250);
        QVERIFY(search->geometry().right() >= bar.width() - 20);

        // narrow: rows, none wider than the bar, none overlapping
        bar.resize(widest + 40, layout->heightForWidth(widest + 40));
        QTRY_VERIFY(buttons.last()->y() > buttons.first()->y());
        for (QPushButton *b : std::as_const(buttons)) {
            QVERIFY(b->geometry().right() <= bar.width());
            for (QPushButton *other : std::as_const(buttons))
                QVERIFY(b == other || !b->geometry().intersects(other->geometry()));
        }
    }

    void hiddenWidgetsTakeNoPlace()
    {
        QWidget bar;
        auto *layout = new FlowLayout(&bar);
        auto *shown = new QPushButton(QStringLiteral("shown"), &bar);
        auto *hidden = new QPushButton(QStringLiteral("a much wider hidden button"), &bar);
        layout->addWidget(shown);
        layout->addWidget(hidden);
        hidden->hide();
        QCOMPARE(layout->minimumSize().width(), shown->minimumSizeHint().width() +
                                                    layout->contentsMargins().left() +
                                                    layout->contentsMargins().right());
    }

    void theLogFilterBarNarrowsToItsWidestGroup()
    {
        Document doc;
        DiagnosticModel model(&doc);
        DiagnosticFilterBar bar(&model);
        // it held ~900 px in one row; wrapped it fits a third of a laptop's 1366 px screen
        QVERIFY2(bar.minimumSizeHint().width() < 1366 / 3,
                 qPrintable(QString::number(bar.minimumSizeHint().width())));
        QVERIFY(bar.sizeHint().width() > bar.minimumSizeHint().width());
    }
};

QTEST_MAIN(TestFlowLayout)
#include "tst_flowlayout.moc"
