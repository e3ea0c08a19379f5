#pragma once

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// One declared PlantUML element: `component "label" as alias <<Stereotype>> {`.
struct PlantUmlDeclaration
{
    QString keyword;         ///< lower-case: "component", "portin", "frame", "queue", ...
    QString alias;           ///< what arrows refer to; the name itself when no `as` is given
    QString label;           ///< `\n` unescaped, stereotypes and `**` taken out, lines trimmed
    QStringList stereotypes; ///< as written, from after the alias and from inside the label
    int parent = -1;         ///< index of the enclosing declaration (the one whose `{` we are in)
    int line = 0;            ///< 1-based
    bool hasBlock = false;   ///< opened a `{ ... }` block

    /// The first line of the label.
    QString firstLine() const { return label.section(QLatin1Char('\n'), 0, 0); }
};

/// One arrow, in data-flow direction: `b <-- a` is read as from = a, to = b.
struct PlantUmlArrow
{
    QString from; ///< alias (or name) as written, quotes and brackets removed
    QString to;
    QString color;        ///< lower-case without '#': "green", "00ff00"; "" when none
    QString label;        ///< the text after ':' ("" when none)
    QString head;         ///< "0" (ball) or "(" (socket) when the arrow ends in one
    bool directed = true; ///< false for `a -- b`: neither end has an arrow head
    int line = 0;
};

/// The syntax of one @startuml ... @enduml block: declarations, their nesting, and arrows.
/// Comments, title, skinparam, !theme, notes and legends are read past; a line that is
/// none of these becomes a warning, never a failure.
struct PlantUmlSyntax
{
    QString title;
    QList<PlantUmlDeclaration> declarations;
    QList<PlantUmlArrow> arrows;
    QStringList notes;    ///< "line 3: ..." what was normalized while reading the syntax
    QStringList warnings; ///< "line 9: cannot read '...'"

    /// Parses `text`: one syntax per @startuml block, or one for the whole text when it has none.
    static QList<PlantUmlSyntax> parse(const QString &text);
    /// The declaration an arrow endpoint names: by alias, else by its label; -1 when none.
    int find(const QString &name) const;
};

} // namespace rosarch
