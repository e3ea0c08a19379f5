#include "plantuml/umlnames.h"
#include "core/editdistance.h"

#include <QList>
#include <QRegularExpression>

#include <algorithm>

namespace rosarch::UmlNames {

QString stereotype(const QString &written, QString *note)
{
    static const QStringList known = {
        AtomicRosNodeClassifier, ComposedRosNodeClassifier, RosNodePart,
        NamespaceStereotype,     ServiceStereotype,         ActionStereotype};
    const QString w = written.trimmed();
    for (const QString &k : known) {
        if (k == w)
            return k;
        if (k.compare(w, Qt::CaseInsensitive) == 0) {
            *note = QStringLiteral("stereotype '%1' read as %2").arg(w, k);
            return k;
        }
    }
    QString best;
    int bestDistance = 3;
    bool tie = false;
    for (const QString &k : known) {
        const int d = editDistance(k.toLower(), w.toLower(), bestDistance + 1);
        if (d < bestDistance) {
            best = k;
            bestDistance = d;
            tie = false;
        } else if (d == bestDistance) {
            tie = true;
        }
    }
    // Short words ("Node" vs "Note") are too close to tell apart by spelling.
    if (best.isEmpty() || tie || w.size() < 5) {
        *note = QStringLiteral("stereotype '%1' is not one of ours; ignored").arg(w);
        return {};
    }
    *note = QStringLiteral("stereotype '%1' read as %2").arg(w, best);
    return best;
}

QString interfaceType(const QString &written, const QString &kind, QString *note)
{
    QString w = written;
    w.remove(QLatin1String("**"));
    w.remove(QRegularExpression(QStringLiteral(R"(\s)")));
    if (w.isEmpty() || w == QLatin1String("?"))
        return w;
    QStringList parts;
    if (w.contains(QLatin1String("::")))
        parts = w.split(QLatin1String("::"), Qt::SkipEmptyParts);
    else if (w.contains(QLatin1Char('/')))
        parts = w.split(QLatin1Char('/'), Qt::SkipEmptyParts);
    else
        parts = w.split(QLatin1Char('.'), Qt::SkipEmptyParts);
    if (parts.size() == 2 && !kind.isEmpty()) {
        parts.insert(1, kind);
        const QString t = parts.join(QLatin1Char('/'));
        *note = QStringLiteral("type '%1' read as %2").arg(w, t);
        return t;
    }
    if (parts.size() == 1)
        *note = QStringLiteral("type '%1' has no package").arg(w);
    return parts.join(QLatin1Char('/'));
}

QString name(const QString &written)
{
    QString n = written.simplified();
    n.remove(QLatin1Char(' '));
    while (n.startsWith(QLatin1Char('/')))
        n.remove(0, 1);
    return n;
}

QString nameSpace(const QString &written)
{
    QStringList parts =
        written.simplified().remove(QLatin1Char(' ')).split(QLatin1Char('/'), Qt::SkipEmptyParts);
    return parts.isEmpty() ? QStringLiteral("/") : parts.join(QLatin1Char('/'));
}

QString launchStem(const QString &written, QString *note)
{
    static const QRegularExpression suffix(
        QStringLiteral(R"(([._]launch)?(\.(py|xml|ya?ml|puml))?$)"),
        QRegularExpression::CaseInsensitiveOption);
    const QString w = written.trimmed();
    QString stem = w;
    stem.remove(suffix);
    if (stem.isEmpty())
        return w;
    if (stem != w)
        *note = QStringLiteral("launch stem '%1' read as %2").arg(w, stem);
    return stem;
}

QString functionName(const QString &written, QString *note)
{
    QString w = written.simplified();
    QString f = w;
    const qsizetype paren = f.indexOf(QLatin1Char('('));
    if (paren > 0)
        f.truncate(paren);
    f = f.trimmed();
    QString bare = f;
    for (const QString &prefix :
         {QStringLiteral("&"), QStringLiteral("self."), QStringLiteral("this->")})
        if (bare.startsWith(prefix))
            bare = bare.mid(prefix.size());
    const qsizetype scope = bare.lastIndexOf(QLatin1String("::"));
    if (scope >= 0)
        bare = bare.mid(scope + 2);
    if (bare != f)
        *note = QStringLiteral("function '%1' read as %2").arg(w, bare);
    return bare;
}

} // namespace rosarch::UmlNames
