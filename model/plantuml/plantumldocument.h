#pragma once

#include "plantuml/plantumlsyntax.h"
#include "plantuml/umldiagram.h"

#include <QList>
#include <QStringList>

namespace rosarch {

/// One parsed PlantUML block seen through our notation: canonical stereotypes per declaration,
/// nesting queries, and the notes and warnings of the diagram being read.
class PlantUmlDocument
{
public:
    /// Resolves the stereotypes of `syntax`; notes about them go to `diagram`.
    PlantUmlDocument(const PlantUmlSyntax &syntax, UmlDiagram *diagram);

    const PlantUmlSyntax &syntax() const { return m_syntax; }
    int size() const { return int(m_syntax.declarations.size()); }
    const PlantUmlDeclaration &at(int index) const { return m_syntax.declarations.at(index); }
    /// True when declaration `index` carries the canonical stereotype `stereotype`.
    bool is(int index, const QString &stereotype) const;
    /// The first declaration with the canonical stereotype; -1 when none.
    int first(const QString &stereotype) const;
    /// portin, portout or port.
    bool isPort(int index) const;
    /// The classifier a declaration sits in: the nearest enclosing component (or stereotyped
    /// classifier); -1 at the top.
    int owner(int index) const;
    /// True when `ancestor` encloses `index` (directly or further out).
    bool encloses(int ancestor, int index) const;
    /// The declarations directly inside `index`.
    QList<int> children(int index) const;

    void note(int line, const QString &text) const;
    void warn(int line, const QString &text) const;
    UmlDiagram *diagram() const { return m_diagram; }
    /// Adds a canonical element to the diagram.
    void add(const QString &kind, const QString &value, int line) const;

private:
    const PlantUmlSyntax &m_syntax;
    UmlDiagram *m_diagram;
    QList<QStringList> m_stereotypes; ///< canonical, per declaration
};

} // namespace rosarch
