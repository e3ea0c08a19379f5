// The internal ids of the tree models: a tag and a payload pack and unpack unchanged up to the
// widest values the bits hold, and the three models that use them stay consistent trees on a
// recovered fixture workspace, every row finding its element and its parent again.
#include "document/document.h"
#include "pipeline/recovery.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/treeindexid.h"

#include <QAbstractItemModelTester>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <functional>
#include <limits>
#include <utility>

using namespace rosarch;

namespace {

enum class Kind
{
    A,
    B,
    C,
    D,
    E,
    F,
    G,
    H
};

using ThreeBits = TreeIndexId<Kind, 3>;
using OneBit = TreeIndexId<Kind, 1>;
using Split = TreeIndexId<Kind, 2, 24>;

constexpr int kIdBits = std::numeric_limits<quintptr>::digits;

// Packing is usable where a constant is needed.
static_assert(ThreeBits(Kind::C, 5).payload() == 5);
static_assert(ThreeBits(Kind::C, 5).tag() == Kind::C);
static_assert(ThreeBits(Kind::C, 5).internalId() == ((5U << 3) | 2U));
static_assert(ThreeBits::kPayloadBits + 3 == kIdBits);
static_assert(Split::kHighBits + 24 + 2 == kIdBits);

/// Every index below `parent` (column 0), depth first.
void walk(const QAbstractItemModel &model, const QModelIndex &parent,
          const std::function<void(const QModelIndex &)> &visit)
{
    for (int row = 0; row < model.rowCount(parent); ++row) {
        const QModelIndex child = model.index(row, 0, parent);
        visit(child);
        walk(model, child, visit);
    }
}

/// Fails when two rows share an internal id and a row number: a proxy that caches rows by
/// the pair (NodeFilterProxyModel) would mix them up.
void verifyRowsDistinct(const QAbstractItemModel &model)
{
    QSet<std::pair<quintptr, int>> seen;
    int rows = 0;
    walk(model, {}, [&](const QModelIndex &index) {
        seen.insert({index.internalId(), index.row()});
        ++rows;
    });
    QCOMPARE(int(seen.size()), rows);
}

} // namespace

class TestTreeIndexId : public QObject
{
    Q_OBJECT
    QTemporaryDir m_ws;
    Recovery m_recovered;

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        // Declared parameters, launch files that set them, and findings of all three stages.
        test::copyTree(test::dataDir(QStringLiteral("params_checks/ws")), m_ws.path());
        m_recovered = recoverWorkspace(m_ws.path());
        QVERIFY(!m_recovered.nodes.nodes.isEmpty());
        QVERIFY(!m_recovered.launch.nodes.isEmpty());
    }

    void roundTrips_data()
    {
        QTest::addColumn<int>("tag");
        QTest::addColumn<qsizetype>("payload");
        QTest::newRow("zero") << 0 << qsizetype(0);
        QTest::newRow("widest tag") << 7 << qsizetype(0);
        QTest::newRow("a row") << 3 << qsizetype(12345);
        QTest::newRow("int's largest") << 5 << qsizetype(std::numeric_limits<int>::max() >> 2);
        QTest::newRow("widest payload") << 0 << ThreeBits::kMaxPayload;
        QTest::newRow("both widest") << 7 << ThreeBits::kMaxPayload;
    }

    void roundTrips()
    {
        QFETCH(int, tag);
        QFETCH(qsizetype, payload);
        QVERIFY(ThreeBits::holds(Kind(tag)));
        QVERIFY(ThreeBits::fits(payload));
        const ThreeBits id(Kind(tag), payload);
        QCOMPARE(id.tag(), Kind(tag));
        QCOMPARE(id.payload(), payload);
        const ThreeBits back = ThreeBits::fromInternalId(id.internalId());
        QCOMPARE(back.tag(), Kind(tag));
        QCOMPARE(back.payload(), payload);
        QVERIFY(back == id);
    }

    void extremesFillTheWord()
    {
        // the payload takes every bit the tag leaves, on this platform's quintptr
        QCOMPARE(ThreeBits::kMaxPayload, qsizetype(~quintptr(0) >> 3));
        QCOMPARE(ThreeBits(Kind::H, ThreeBits::kMaxPayload).internalId(), ~quintptr(0));
        QCOMPARE(ThreeBits(Kind::A, ThreeBits::kMaxPayload).internalId(), ~quintptr(0) << 3);
        QCOMPARE(ThreeBits(Kind::H).internalId(), quintptr(7));
        QCOMPARE(ThreeBits().internalId(), quintptr(0));
        // neither part bleeds into the other
        QCOMPARE(ThreeBits(Kind::H).payload(), qsizetype(0));
        QCOMPARE(ThreeBits(Kind::A, ThreeBits::kMaxPayload).tag(), Kind::A);
        // with a one-bit tag the payload is as wide as a non-negative qsizetype
        QCOMPARE(OneBit::kMaxPayload, std::numeric_limits<qsizetype>::max());
        QCOMPARE(OneBit(Kind::B, OneBit::kMaxPayload).internalId(), ~quintptr(0));
        QCOMPARE(OneBit::fromInternalId(~quintptr(0)).payload(), OneBit::kMaxPayload);
        QCOMPARE(OneBit::fromInternalId(~quintptr(0)).tag(), Kind::B);
    }

    void guardsWhatDoesNotFit()
    {
        QVERIFY(ThreeBits::fits(0));
        QVERIFY(ThreeBits::fits(ThreeBits::kMaxPayload));
        QVERIFY(!ThreeBits::fits(ThreeBits::kMaxPayload + 1));
        QVERIFY(!ThreeBits::fits(-1)); // a row of -1 (not found) is never packed
        QVERIFY(!OneBit::fits(-1));
        QVERIFY(OneBit::fits(std::numeric_limits<qsizetype>::max()));
        QVERIFY(ThreeBits::holds(Kind::H));
        QVERIFY(OneBit::holds(Kind::B));
        QVERIFY(!OneBit::holds(Kind::C));
        QVERIFY(!ThreeBits::holds(Kind(8)));
        QVERIFY(!ThreeBits::holds(Kind(-1)));
    }

    void splitPayloadsRoundTrip()
    {
        QCOMPARE(Split::kMaxLow, qsizetype((1 << 24) - 1));
        QCOMPARE(Split::kMaxHigh, qsizetype(~quintptr(0) >> 26));
        const QList<std::pair<qsizetype, qsizetype>> parts{{0, 0},
                                                           {0, Split::kMaxLow},
                                                           {Split::kMaxHigh, 0},
                                                           {Split::kMaxHigh, Split::kMaxLow},
                                                           {4711, 42}};
        for (const auto &[high, low] : parts) {
            QVERIFY(Split::fits(high, low));
            const Split id = Split::split(Kind::C, high, low);
            const Split back = Split::fromInternalId(id.internalId());
            QCOMPARE(back.tag(), Kind::C);
            QCOMPARE(back.high(), high);
            QCOMPARE(back.low(), low);
            QCOMPARE(back.payload(), (high << 24) | low);
        }
        QCOMPARE(Split::split(Kind::D, Split::kMaxHigh, Split::kMaxLow).internalId(), ~quintptr(0));
        QVERIFY(!Split::fits(Split::kMaxHigh + 1, 0));
        QVERIFY(!Split::fits(0, Split::kMaxLow + 1));
        QVERIFY(!Split::fits(-1, 0));
        QVERIFY(!Split::fits(0, -1));
        // a whole payload reads as its two parts
        QCOMPARE(Split(Kind::B, 5).high(), qsizetype(0));
        QCOMPARE(Split(Kind::B, 5).low(), qsizetype(5));
    }

    void atomicNodeModelOnAFixture()
    {
        Document doc;
        AtomicNodeModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setRecovery(m_recovered);

        int nodes = 0;
        int ports = 0;
        int parameters = 0;
        for (int p = 0; p < model.rowCount(); ++p) {
            const QModelIndex package = model.index(p, 0);
            QCOMPARE(model.kind(package), AtomicNodeModel::ItemKind::Package);
            QCOMPARE(model.parent(package), QModelIndex());
            for (int r = 0; r < model.rowCount(package); ++r) {
                const QModelIndex nodeRow = model.index(r, 0, package);
                QCOMPARE(model.kind(nodeRow), AtomicNodeModel::ItemKind::Node);
                const AtomicNode *n = model.node(nodeRow);
                QVERIFY(n);
                QCOMPARE(model.parent(nodeRow), package);
                QCOMPARE(model.nodeIndex(n->id), nodeRow);
                ++nodes;
                for (int c = 0; c < model.rowCount(nodeRow); ++c) {
                    const QModelIndex child = model.index(c, 0, nodeRow);
                    QCOMPARE(model.parent(child), nodeRow);
                    QCOMPARE(model.node(child), n);
                    if (c < n->ports.size()) {
                        QCOMPARE(model.kind(child), AtomicNodeModel::ItemKind::Port);
                        QCOMPARE(model.port(child), &n->ports[c]);
                        QCOMPARE(model.portIndex(n->id, n->ports[c].id), child);
                        ++ports;
                        continue;
                    }
                    QCOMPARE(model.kind(child), AtomicNodeModel::ItemKind::Parameters);
                    QCOMPARE(model.parametersIndex(n->id), child);
                    QCOMPARE(model.rowCount(child), int(n->parameters.size()));
                    for (int k = 0; k < model.rowCount(child); ++k) {
                        const QModelIndex parameter = model.index(k, 0, child);
                        QCOMPARE(model.kind(parameter), AtomicNodeModel::ItemKind::Parameter);
                        QCOMPARE(model.parameter(parameter), &n->parameters[k]);
                        QCOMPARE(model.parent(parameter), child);
                        QCOMPARE(model.parent(model.parent(parameter)), nodeRow);
                        QCOMPARE(model.rowCount(parameter), 0);
                        ++parameters;
                    }
                }
            }
        }
        int declared = 0;
        int allPorts = 0;
        for (const AtomicNode &n : m_recovered.nodes.nodes) {
            declared += int(n.parameters.size());
            allPorts += int(n.ports.size());
        }
        QCOMPARE(nodes, int(m_recovered.nodes.nodes.size()));
        QCOMPARE(ports, allPorts);
        QCOMPARE(parameters, declared);
        QVERIFY(parameters > 0); // the fixture has parameter rows to walk
        verifyRowsDistinct(model);
    }

    void launchTreeModelOnAFixture()
    {
        Document doc;
        LaunchTreeModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setRecovery(m_recovered);

        QSet<QString> nodes;
        int parameters = 0;
        walk(model, {}, [&](const QModelIndex &row) {
            if (model.kind(row) != LaunchTreeModel::ItemKind::Node)
                return;
            const NodeInstance *n = model.node(row);
            QVERIFY(n);
            QCOMPARE(model.nodeIndex(n->id), row);
            nodes.insert(n->id);
            const int children = model.rowCount(row);
            if (n->effectiveParameters.isEmpty()) {
                QVERIFY(children == 0 || model.kind(model.index(children - 1, 0, row)) !=
                                             LaunchTreeModel::ItemKind::Parameters);
                return;
            }
            // the "Parameters" row comes after the node's own children
            const QModelIndex group = model.index(children - 1, 0, row);
            QCOMPARE(model.kind(group), LaunchTreeModel::ItemKind::Parameters);
            QCOMPARE(model.parent(group), row);
            QVERIFY(!model.parameter(group));
            QCOMPARE(model.rowCount(group), int(n->effectiveParameters.size()));
            for (int k = 0; k < model.rowCount(group); ++k) {
                const QModelIndex parameter = model.index(k, 0, group);
                QCOMPARE(model.kind(parameter), LaunchTreeModel::ItemKind::Parameter);
                QCOMPARE(model.parameter(parameter), &n->effectiveParameters[k]);
                QCOMPARE(model.parent(parameter), group);
                QCOMPARE(model.isActive(parameter), model.isActive(row));
                QCOMPARE(model.rowCount(parameter), 0);
                ++parameters;
            }
        });
        int effective = 0;
        QSet<QString> all;
        for (const NodeInstance &n : m_recovered.launch.nodes) {
            all.insert(n.id);
            effective += int(n.effectiveParameters.size());
        }
        QStringList shown = nodes.values();
        QStringList recovered = all.values();
        shown.sort();
        recovered.sort();
        QCOMPARE(shown, recovered);
        QCOMPARE(parameters, effective);
        QVERIFY(parameters > 0);
        verifyRowsDistinct(model);
    }

    void diagnosticModelOnAFixture_data()
    {
        QTest::addColumn<int>("groupingValue");
        QTest::newRow("flat") << int(DiagnosticModel::Grouping::None);
        QTest::newRow("by kind") << int(DiagnosticModel::Grouping::Kind);
        QTest::newRow("by package") << int(DiagnosticModel::Grouping::Package);
    }

    void diagnosticModelOnAFixture()
    {
        QFETCH(int, groupingValue);
        const auto grouping = DiagnosticModel::Grouping(groupingValue);
        Document doc;
        DiagnosticModel model(&doc);
        QAbstractItemModelTester tester(&model,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        doc.setRecovery(m_recovered);
        model.setGrouping(grouping);
        QVERIFY(model.shown() > 1);

        QList<const Diagnostic *> findings;
        for (int r = 0; r < model.rowCount(); ++r) {
            const QModelIndex top = model.index(r, 0);
            QCOMPARE(model.parent(top), QModelIndex());
            if (grouping == DiagnosticModel::Grouping::None) {
                QVERIFY(model.diagnostic(top));
                QCOMPARE(model.rowCount(top), 0);
                findings << model.diagnostic(top);
                continue;
            }
            QVERIFY(!model.diagnostic(top));
            QVERIFY(top.data(DiagnosticModel::GroupRole).toBool());
            QVERIFY(model.rowCount(top) > 0);
            const QString label = top.data().toString();
            for (int c = 0; c < model.rowCount(top); ++c) {
                const QModelIndex finding = model.index(c, 0, top);
                QCOMPARE(model.parent(finding), top);
                QCOMPARE(model.rowCount(finding), 0);
                const Diagnostic *d = model.diagnostic(finding);
                QVERIFY(d);
                // the finding is in its own group
                if (grouping == DiagnosticModel::Grouping::Kind)
                    QVERIFY2(label.startsWith(d->code), qPrintable(label));
                else if (!model.package(finding).isEmpty())
                    QVERIFY2(label.startsWith(model.package(finding)), qPrintable(label));
                findings << d;
            }
        }
        QCOMPARE(int(findings.size()), model.shown());
        QCOMPARE(int(QSet<const Diagnostic *>(findings.cbegin(), findings.cend()).size()),
                 model.shown());
        verifyRowsDistinct(model);
    }
};

QTEST_MAIN(TestTreeIndexId)
#include "tst_treeindexid.moc"
