// The tree filter of the node list and the launch tree: which rows it keeps, and filtering as
// a person types over a tree too large to match between two keys.
#include "widgets/nodefilterproxymodel.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QStandardItemModel>
#include <QTest>

using namespace rosarch;

namespace {

/// groups × nodes × ports: "group g" → "node g.n" (type "Type<n % 7>") → "port g.n.p".
void fill(QStandardItemModel &model, int groups, int nodes, int ports)
{
    model.clear();
    model.setColumnCount(2);
    for (int g = 0; g < groups; ++g) {
        auto *group = new QStandardItem(QStringLiteral("group %1").arg(g));
        for (int n = 0; n < nodes; ++n) {
            QList<QStandardItem *> node{
                new QStandardItem(QStringLiteral("node %1.%2").arg(g).arg(n)),
                new QStandardItem(QStringLiteral("Type%1").arg(n % 7))};
            for (int p = 0; p < ports; ++p)
                node.first()->appendRow(
                    {new QStandardItem(QStringLiteral("port %1.%2.%3").arg(g).arg(n).arg(p)),
                     new QStandardItem()});
            group->appendRow(node);
        }
        model.appendRow({group, new QStandardItem()});
    }
}

/// Every row the proxy keeps, by name, depth first.
QStringList kept(const QAbstractItemModel *model, const QModelIndex &parent = {})
{
    QStringList out;
    for (int row = 0; row < model->rowCount(parent); ++row) {
        const QModelIndex index = model->index(row, 0, parent);
        out << index.data().toString() << kept(model, index);
    }
    return out;
}

/// What the filter of `text` keeps, found without the proxy: a matching row, its ancestors and
/// all rows under it.
QStringList expected(const QStandardItemModel &model, const QString &text)
{
    QStringList out;
    std::function<bool(const QModelIndex &)> matchesBelow = [&](const QModelIndex &index) {
        for (int row = 0; row < model.rowCount(index); ++row) {
            const QModelIndex child = model.index(row, 0, index);
            if (child.data().toString().contains(text, Qt::CaseInsensitive) ||
                child.siblingAtColumn(1).data().toString().contains(text, Qt::CaseInsensitive) ||
                matchesBelow(child))
                return true;
        }
        return false;
    };
    std::function<void(const QModelIndex &, bool)> walk = [&](const QModelIndex &parent,
                                                              bool above) {
        for (int row = 0; row < model.rowCount(parent); ++row) {
            const QModelIndex index = model.index(row, 0, parent);
            const bool self =
                index.data().toString().contains(text, Qt::CaseInsensitive) ||
                index.siblingAtColumn(1).data().toString().contains(text, Qt::CaseInsensitive);
            if (above || self || matchesBelow(index)) {
                out << index.data().toString();
                walk(index, above || self);
            }
        }
    };
    walk({}, false);
    return out;
}

} // namespace

class TestNodeFilterProxyModel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void keepsMatchesTheirAncestorsAndTheirRows_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("a port") << QStringLiteral("port 1.2.3");
        QTest::newRow("a node's type") << QStringLiteral("type3");
        QTest::newRow("a group") << QStringLiteral("group 2");
        QTest::newRow("nothing") << QStringLiteral("no such row");
    }
    void keepsMatchesTheirAncestorsAndTheirRows()
    {
        QFETCH(QString, text);
        QStandardItemModel model;
        fill(model, 4, 5, 4);
        NodeFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        QAbstractItemModelTester tester(&proxy,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        const QStringList want = expected(model, text);
        // both ways in: a regular expression (tests, other callers) and typed text
        proxy.setFilterRegularExpression(QRegularExpression(
            QRegularExpression::escape(text), QRegularExpression::CaseInsensitiveOption));
        QCOMPARE(kept(&proxy), want);
        proxy.setFilterRegularExpression(QString());
        QCOMPARE(kept(&proxy).size(), 4 + 4 * 5 + 4 * 5 * 4);
        QSignalSpy applied(&proxy, &NodeFilterProxyModel::filterApplied);
        proxy.setFilterTextInSlices(text);
        QCOMPARE(applied.size(), 1); // a small tree filters at once
        QVERIFY(!proxy.isFiltering());
        QCOMPARE(kept(&proxy), want);
    }

    void matchesItselfIsTheRowsOwnText()
    {
        QStandardItemModel model;
        fill(model, 2, 2, 2);
        NodeFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        proxy.setFilterTextInSlices(QStringLiteral("node 1.1"));
        const QModelIndex group = proxy.index(0, 0);
        QCOMPARE(group.data().toString(), QStringLiteral("group 1"));
        QVERIFY(!proxy.matchesItself(group)); // kept for its node
        const QModelIndex node = proxy.index(0, 0, group);
        QVERIFY(proxy.matchesItself(node));
        QVERIFY(!proxy.matchesItself(proxy.index(0, 0, node))); // kept under its node
    }

    void aLargeTreeIsFilteredBetweenEventsAndTheLastTextWins()
    {
        QStandardItemModel model;
        fill(model, 40, 50, 40); // 82,040 rows: more than one slice reads
        NodeFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        QAbstractItemModelTester tester(&proxy,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy applied(&proxy, &NodeFilterProxyModel::filterApplied);
        proxy.setFilterTextInSlices(QStringLiteral("port 3"));
        QVERIFY(proxy.isFiltering());
        QCOMPARE(proxy.rowCount(), 40); // the rows stay as they were meanwhile
        // the next key before the rows are matched: only its filter applies
        proxy.setFilterTextInSlices(QStringLiteral("port 3.4"));
        QVERIFY(applied.wait(10000));
        QVERIFY(!proxy.isFiltering());
        QCOMPARE(applied.size(), 1);
        QCOMPARE(kept(&proxy), expected(model, QStringLiteral("port 3.4")));
        // a narrower text is matched over the rows read before
        proxy.setFilterTextInSlices(QStringLiteral("port 3.49.1"));
        QTRY_COMPARE(applied.size(), 2);
        QCOMPARE(kept(&proxy), expected(model, QStringLiteral("port 3.49.1")));
        // and "" shows every row again, at once
        proxy.setFilterTextInSlices(QString());
        QCOMPARE(applied.size(), 3);
        QCOMPARE(proxy.rowCount(), 40);
    }

    void aChangeOfTheRowsWhileMatchingIsFollowed()
    {
        QStandardItemModel model;
        fill(model, 40, 50, 20);
        NodeFilterProxyModel proxy;
        proxy.setSourceModel(&model);
        QAbstractItemModelTester tester(&proxy,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QSignalSpy applied(&proxy, &NodeFilterProxyModel::filterApplied);
        proxy.setFilterTextInSlices(QStringLiteral("renamed"));
        QVERIFY(proxy.isFiltering());
        model.item(7)->child(3)->child(2)->setText(QStringLiteral("renamed port"));
        model.removeRow(0);
        QVERIFY(applied.wait(10000));
        QCOMPARE(kept(&proxy), (QStringList{QStringLiteral("group 7"), QStringLiteral("node 7.3"),
                                            QStringLiteral("renamed port")}));
        // a change after the filter applied keeps the rows it should
        model.item(0)->child(0)->setText(QStringLiteral("renamed node"));
        QCOMPARE(kept(&proxy).mid(0, 2),
                 (QStringList{QStringLiteral("group 1"), QStringLiteral("renamed node")}));
    }
};

QTEST_MAIN(TestNodeFilterProxyModel)
#include "tst_nodefilterproxymodel.moc"
