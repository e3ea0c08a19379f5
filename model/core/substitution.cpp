#include "core/substitution.h"

#include <QStringList>

namespace rosarch {

Substitution Substitution::literal(const QString &text)
{
    Substitution s;
    s.kind = Kind::Text;
    s.text = text;
    return s;
}

Substitution Substitution::unknown(const QString &expression)
{
    Substitution s;
    s.kind = Kind::Unknown;
    s.text = expression;
    return s;
}

Substitution Substitution::configuration(const QString &name)
{
    Substitution s;
    s.kind = Kind::LaunchConfiguration;
    s.text = name;
    return s;
}

Substitution Substitution::concat(QList<Substitution> parts)
{
    if (parts.size() == 1)
        return parts.first();
    Substitution s;
    s.kind = Kind::Concat;
    s.parts = std::move(parts);
    return s;
}

Substitution Substitution::function(const QString &name, QList<Substitution> arguments)
{
    Substitution s;
    s.kind = Kind::Function;
    s.text = name;
    s.parts = std::move(arguments);
    return s;
}

bool Substitution::findsPackageByConfiguration(int depth) const
{
    if (depth > 32)
        return false;
    const bool share = kind == Kind::FindPackageShare || kind == Kind::FindPackagePrefix;
    for (const Substitution &p : parts) {
        if (share && p.kind == Kind::LaunchConfiguration)
            return true;
        if (share && p.kind == Kind::Concat)
            for (const Substitution &q : p.parts)
                if (q.kind == Kind::LaunchConfiguration)
                    return true;
        if (p.findsPackageByConfiguration(depth + 1))
            return true;
    }
    return false;
}

QString Substitution::describe() const
{
    auto joined = [&](const QString &sep) {
        QStringList out;
        for (const Substitution &p : parts)
            out << p.describe();
        return out.join(sep);
    };
    switch (kind) {
    case Kind::Text:
        return text;
    case Kind::LaunchConfiguration:
        return QStringLiteral("$(var %1)").arg(text);
    case Kind::EnvironmentVariable:
        return QStringLiteral("$(env %1)").arg(text);
    case Kind::FindPackageShare:
        return QStringLiteral("$(find-pkg-share %1)").arg(joined(QString()));
    case Kind::FindPackagePrefix:
        return QStringLiteral("$(find-pkg-prefix %1)").arg(joined(QString()));
    case Kind::PathJoin:
        return joined(QStringLiteral("/"));
    case Kind::Concat:
        return joined(QString());
    case Kind::Eval:
        return QStringLiteral("$(eval %1)").arg(joined(QString()));
    case Kind::ThisLaunchFileDir:
        return QStringLiteral("$(dirname)");
    case Kind::ThisLaunchFile:
        return QStringLiteral("$(filename)");
    case Kind::RewrittenYaml:
        return QStringLiteral("RewrittenYaml(%1)").arg(joined(QStringLiteral(", ")));
    case Kind::Unknown:
        return text;
    case Kind::Function: {
        QStringList args;
        for (const Substitution &p : parts)
            args << p.describe();
        return QStringLiteral("$(%1 %2)").arg(text, args.join(QLatin1Char(' ')));
    }
    }
    return text;
}

} // namespace rosarch
