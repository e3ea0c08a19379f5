#include "plantuml/plantumldocument.h"
#include "plantuml/umlnames.h"

namespace rosarch {

PlantUmlDocument::PlantUmlDocument(const PlantUmlSyntax &syntax, UmlDiagram *diagram)
    : m_syntax(syntax), m_diagram(diagram)
{
    for (const PlantUmlDeclaration &d : syntax.declarations) {
        QStringList canonical;
        for (const QString &written : d.stereotypes) {
            // Our writer's nested subsystem: structure only, no element of its own (§4), so
            // it is known (no "not one of ours" note) but read as a plain container.
            if (written.trimmed().compare(QLatin1String("Subsystem"), Qt::CaseInsensitive) == 0) {
                canonical << QStringLiteral("Subsystem");
                continue;
            }
            QString why;
            const QString s = UmlNames::stereotype(written, &why);
            if (!why.isEmpty())
                note(d.line, why);
            if (!s.isEmpty())
                canonical << s;
        }
        m_stereotypes << canonical;
    }
}

bool PlantUmlDocument::is(int index, const QString &stereotype) const
{
    return index >= 0 && index < m_stereotypes.size() &&
           m_stereotypes.at(index).contains(stereotype);
}

int PlantUmlDocument::first(const QString &stereotype) const
{
    for (int i = 0; i < size(); ++i)
        if (is(i, stereotype))
            return i;
    return -1;
}

bool PlantUmlDocument::isPort(int index) const
{
    const QString &k = at(index).keyword;
    return k == QLatin1String("portin") || k == QLatin1String("portout") ||
           k == QLatin1String("port");
}

int PlantUmlDocument::owner(int index) const
{
    for (int p = at(index).parent; p >= 0; p = at(p).parent) {
        if (at(p).keyword == QLatin1String("component") || at(p).keyword == QLatin1String("node") ||
            is(p, UmlNames::AtomicRosNodeClassifier) ||
            is(p, UmlNames::ComposedRosNodeClassifier) || is(p, UmlNames::RosNodePart))
            return p;
    }
    return -1;
}

bool PlantUmlDocument::encloses(int ancestor, int index) const
{
    // Indexes come from the reader's searches, which answer -1 for "none" (found by fuzzing):
    // nothing encloses what does not exist. The steps are bounded by the declarations.
    if (index < 0 || index >= size())
        return false;
    int steps = 0;
    for (int p = at(index).parent; p >= 0 && p < size() && steps <= size();
         p = at(p).parent, ++steps)
        if (p == ancestor)
            return true;
    return false;
}

QList<int> PlantUmlDocument::children(int index) const
{
    QList<int> out;
    for (int i = 0; i < size(); ++i)
        if (at(i).parent == index)
            out << i;
    return out;
}

void PlantUmlDocument::note(int line, const QString &text) const
{
    m_diagram->notes << QStringLiteral("line %1: %2").arg(line).arg(text);
}

void PlantUmlDocument::warn(int line, const QString &text) const
{
    m_diagram->warnings << QStringLiteral("line %1: %2").arg(line).arg(text);
}

void PlantUmlDocument::add(const QString &kind, const QString &value, int line) const
{
    m_diagram->elements << UmlElement{kind, value, line, {}};
}

} // namespace rosarch
