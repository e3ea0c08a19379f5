#pragma once

#include <QCoreApplication>
#include <QString>

namespace rosarch {

class Document;

/// A node class's description as it is in effect, and where it comes from: the code's own
/// documentation, an accepted suggestion, or a person's correction (`describe`), the last
/// of them that applies, as Document applies them. One query for every view that shows it.
struct NodeDescription
{
    Q_DECLARE_TR_FUNCTIONS(rosarch::NodeDescription)
public:
    enum class Source
    {
        None,       ///< nothing describes the class
        Code,       ///< analysis found it in the code (a doc comment, a docstring)
        Suggestion, ///< an accepted suggestion (e.g. from the LLM)
        Correction  ///< a person wrote it
    };

    QString text;
    Source source = Source::None;

    /// The description in effect of class `nodeId` in `document` (none for an unknown id).
    static NodeDescription of(const Document &document, const QString &nodeId);
    /// For people: "from the code", "from an accepted suggestion", "written by a person";
    /// "No description in the code" when there is none.
    QString sourceText() const;
};

} // namespace rosarch
