#include "document/nodedescription.h"
#include "document/document.h"
#include "suggestions/nodedocumentation.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QHash>

namespace rosarch {

namespace {

/// The class's own documentation, read from its file when a view first asks and again when
/// the file changes (views ask on the UI thread only).
QString documentationInCode(const QString &root, const AtomicNode &node)
{
    struct Read
    {
        QDateTime modified;
        QString text;
    };
    static QHash<QString, Read> read;
    const QFileInfo file(QDir(root).filePath(node.evidence.file));
    const QString key =
        QStringLiteral("%1\n%2\n%3")
            .arg(file.filePath(), node.qualifiedName, QString::number(node.evidence.line));
    const QDateTime modified = file.lastModified();
    const auto known = read.constFind(key);
    if (known != read.constEnd() && known->modified == modified)
        return known->text;
    const std::optional<NodeDocumentation> doc =
        NodeDocumentation::read(SuggestionSource(root), node);
    const QString text = doc ? doc->text : QString();
    read.insert(key, {modified, text});
    return text;
}

} // namespace

NodeDescription NodeDescription::of(const Document &document, const QString &nodeId)
{
    const AtomicNode *node = document.atomicNodes().node(nodeId);
    if (!node)
        return {};
    NodeDescription d{node->description, node->description.isEmpty() ? Source::None : Source::Code};
    if (d.source == Source::None && !node->evidence.file.isEmpty() &&
        !document.workspaceRoot().isEmpty()) {
        // nothing accepted or written: what the class's own documentation says, without
        // running Suggestions
        d.text = documentationInCode(document.workspaceRoot(), *node);
        d.source = d.text.isEmpty() ? Source::None : Source::Code;
        return d;
    }
    // The same order ProjectSession applies them in: the code, accepted suggestions, then a
    // person's own edits. The text is already the one in effect; only its source is asked.
    bool described = false;
    for (const Correction &c : document.session()->corrections())
        described = described || c.kind == Correction::Kind::Describe;
    if (described) { // the keys are only made when a correction could name the class
        const QString key = document.session()->keyOf(nodeId);
        for (const Correction &c : document.session()->corrections())
            if (c.kind == Correction::Kind::Describe && !key.isEmpty() && c.target == key)
                d.source = Source::Correction;
    }
    if (d.source == Source::Correction)
        return d;
    for (const SuggestionDecision &s : document.session()->decisions())
        if (s.kind == Suggestion::Kind::NodeDescription &&
            s.status == Suggestion::Status::Accepted && s.targetId == nodeId &&
            s.proposal == node->description)
            d.source = Source::Suggestion;
    return d;
}

QString NodeDescription::sourceText() const
{
    switch (source) {
    case Source::None:
        return tr("No description in the code");
    case Source::Code:
        return tr("from the code");
    case Source::Suggestion:
        return tr("from an accepted suggestion");
    case Source::Correction:
        return tr("written by a person");
    }
    return {};
}

} // namespace rosarch
