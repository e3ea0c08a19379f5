#pragma once

#include "core/launchdependencies.h"
#include "core/substitution.h"

#include <QMap>
#include <QSet>
#include <QString>
#include <QStringList>

#include <functional>

namespace rosarch {

/// Evaluates substitutions against launch configurations, statically. A package's share
/// folder evaluates to "$(find-pkg-share pkg)" so that include paths stay recognisable;
/// what cannot be decided is reported in `unresolved` with the guess used instead.
class SubstitutionEvaluator
{
public:
    /// The kind of Unresolved entry for a value past the size budget (kMaxValueChars).
    static constexpr const char *kEvaluationLimit = "evaluation-limit";

    struct Result
    {
        QString value;
        QList<Unresolved> unresolved;
        bool isResolved() const { return unresolved.isEmpty(); }
    };

    /// `guessed` names the configurations whose value is itself a guess (it was evaluated from
    /// something unresolved): a value read from one of them is reported as unresolved too.
    SubstitutionEvaluator(const QMap<QString, QString> &configurations, QString launchFileDir,
                          const QSet<QString> *guessed = nullptr);

    Result evaluate(const Substitution &s) const;
    /// A launch condition's truth: "true"/"1" and "false"/"0"/"" (case-insensitive). Anything
    /// else, or an unresolved expression, counts as true (the best guess) and is reported.
    bool isTrue(const Substitution &s, QList<Unresolved> *unresolved) const;

    /// Evaluates the Python expressions launch files put in PythonExpression / $(eval), as
    /// PythonLaunchEval does. Returns false when the value is not known exactly.
    static bool evaluatePython(const QString &expression, QString *value);

private:
    /// Appends the value of `s` to r->value, or nothing (and an Unresolved entry) when that
    /// would exceed the size budget.
    void evaluateInto(const Substitution &s, Result *r, int depth) const;
    void evaluateOne(const Substitution &s, Result *r, int depth) const;
    /// The value of a launch function (Substitution::Kind::Function).
    QString function(const Substitution &s, Result *r, int depth) const;

    const QMap<QString, QString> &m_configurations;
    QString m_launchFileDir;
    const QSet<QString> *m_guessed;
};

} // namespace rosarch
