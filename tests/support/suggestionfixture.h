#pragma once

// The example workspace recovered once, with its deterministic suggestions, for the tests of
// suggestions and decisions; settings and decisions kept in a temporary home.
#include "document/document.h"
#include "pipeline/recovery.h"
#include "suggestions/suggestionengine.h"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

namespace rosarch::test {

/// The API key the tests configure; it must never be written anywhere.
inline const QString kSecret = QStringLiteral("sk-flow-secret-0123456789");

inline QString exampleWorkspace()
{
    return QFileInfo(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                         .filePath(QStringLiteral("resources/example_ws")))
        .canonicalFilePath();
}

struct SuggestionFixture
{
    QTemporaryDir home;
    Recovery recovery;
    SuggestionReport deterministic;

    /// Before the first QSettings / QStandardPaths use: nothing of the test leaves `home`.
    /// Recovers the example workspace and runs the deterministic suggestions on it.
    bool setUp()
    {
        if (!home.isValid())
            return false;
        qputenv("XDG_DATA_HOME", home.filePath(QStringLiteral("data")).toUtf8());
        qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral("config")).toUtf8());
        qputenv("ROSARCH_LLM_API_KEY", kSecret.toUtf8());
        qunsetenv("ROSARCH_LLM_ENDPOINT");
        qunsetenv("ROSARCH_PROMPT_DIR");
        if (!QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)
                 .startsWith(home.path()))
            return false;
        recovery = recoverWorkspace(exampleWorkspace());
        recovery.nodes.workspaceRoot = exampleWorkspace();
        deterministic =
            SuggestionEngine(exampleWorkspace(), recovery, SuggestionEngine::Options()).run();
        return deterministic.suggestions.size() == 9; // 8 descriptions + 1 grouping
    }

    /// A Document on example_ws with the deterministic suggestions, all pending.
    void load(Document &doc) const
    {
        doc.setRecovery(recovery);
        doc.session()->setSuggestions(deterministic);
    }
};

/// The first suggestion of `kind` in `doc` (fails the test run when there is none).
inline const Suggestion &firstOf(const Document &doc, Suggestion::Kind kind)
{
    for (const Suggestion &s : doc.session()->suggestions())
        if (s.kind == kind)
            return s;
    qFatal("no suggestion of that kind");
}

} // namespace rosarch::test
