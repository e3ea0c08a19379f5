// mapLargestFirst hands the largest files out first and gives the results back in the files'
// own order, whatever their sizes.
#include "workspace/largestfirst.h"

#include <QtTest>

using namespace rosarch;

namespace {

QList<SourceFile> filesOfSizes(const QList<qint64> &sizes)
{
    QList<SourceFile> files;
    for (qsizetype i = 0; i < sizes.size(); ++i) {
        SourceFile f;
        f.path = QStringLiteral("f%1.cpp").arg(i);
        f.size = sizes.at(i);
        files.append(f);
    }
    return files;
}

QList<const SourceFile *> pointers(const QList<SourceFile> &files)
{
    QList<const SourceFile *> out;
    for (const SourceFile &f : files)
        out.append(&f);
    return out;
}

} // namespace

class TestLargestFirst : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void resultsKeepTheFilesOrder_data()
    {
        QTest::addColumn<QList<qint64>>("sizes");
        QTest::newRow("none") << QList<qint64>{};
        QTest::newRow("one") << QList<qint64>{7};
        QTest::newRow("ascending") << QList<qint64>{1, 2, 3, 4, 5, 6, 7, 8};
        QTest::newRow("mixed with ties") << QList<qint64>{5, 100, 1, 100, 50, 0, 5, 99999};
        QList<qint64> many;
        for (int i = 0; i < 500; ++i)
            many.append((i * 7919) % 1000);
        QTest::newRow("500 files") << many;
    }
    void resultsKeepTheFilesOrder()
    {
        QFETCH(QList<qint64>, sizes);
        const QList<SourceFile> files = filesOfSizes(sizes);
        const QList<QString> results =
            mapLargestFirst<QString>(pointers(files), [](const SourceFile *f) { return f->path; });
        QCOMPARE(results.size(), files.size());
        for (qsizetype i = 0; i < files.size(); ++i)
            QCOMPARE(results.at(i), files.at(i).path);
    }

    void theLargestFilesGoFirst()
    {
        const QList<SourceFile> files = filesOfSizes({3, 10, 400, 2, 900, 1, 5, 10, 7, 6});
        QCOMPARE(largestFirst(pointers(files)),
                 (QList<qsizetype>{4, 2, 1, 7, 8, 9, 6, 0, 3, 5})); // the two 10s in order
        QVERIFY(largestFirst({}).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestLargestFirst)
#include "tst_largestfirst.moc"
