#pragma once

#include "nodes/python/pythonscopeindex.h"
#include "syntax/syntaxtree.h"

#include <QHash>
#include <QSet>
#include <QString>
#include <QStringList>

namespace rosarch {

/// The names a Python file binds at module level: its imports (plain, aliased, relative and
/// wildcard) and its own classes and top-level functions.
class PythonImports
{
public:
    PythonImports(const SyntaxTree &tree, const PythonScopeIndex &scopes, QString modulePath);

    /// Qualifies a dotted name through the imports and the file's own definitions.
    QString qualify(const QString &dotted) const;

private:
    QString resolveRelative(const SyntaxTree &tree, TSNode relativeImport) const;

    QString m_modulePath;
    QHash<QString, QString> m_bindings; ///< local name -> qualified dotted name
    QStringList m_wildcards;            ///< modules imported with *
    QSet<QString> m_definitions;        ///< classes and top-level functions of this file
};

} // namespace rosarch
