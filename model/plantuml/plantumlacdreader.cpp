#include "plantuml/plantumlacdreader.h"
#include "plantuml/umlnames.h"

#include <QHash>
#include <QRegularExpression>

namespace rosarch {

namespace {

enum class Container
{
    None,
    Topic,
    Service,
    Action
};

struct Labelled
{
    QString text;
    int line = 0;
};

bool isPortId(const QString &text)
{
    static const QRegularExpression id(QStringLiteral(R"(^(s|p|ps|rs|pa|ra)\d*$)"));
    return id.match(text).hasMatch();
}

/// "msg", "srv" or "action" when the written type says so; "" otherwise.
QString writtenKind(const QString &label)
{
    QString why;
    const QStringList parts = UmlNames::interfaceType(label, {}, &why).split(QLatin1Char('/'));
    return parts.size() == 3 ? parts.at(1) : QString();
}

class AcdReader
{
public:
    AcdReader(const PlantUmlDocument &doc, int top) : m_doc(doc), m_top(top) {}

    void read()
    {
        const PlantUmlDeclaration &t = m_doc.at(m_top);
        QString className = t.firstLine().isEmpty() ? t.alias : t.firstLine();
        const qsizetype scope = className.lastIndexOf(QLatin1String("::"));
        if (scope >= 0) {
            m_doc.note(t.line, QStringLiteral("class name '%1' read as %2")
                                   .arg(className, className.mid(scope + 2)));
            className = className.mid(scope + 2);
        }
        m_doc.diagram()->name = className;
        m_doc.add(UmlKind::ArcName, className, t.line);
        if (m_doc.is(m_top, UmlNames::AtomicRosNodeClassifier))
            m_doc.add(UmlKind::ArcStereotype, UmlNames::AtomicRosNodeClassifier, t.line);
        for (int i = 0; i < m_doc.size(); ++i)
            if (i != m_top && !m_doc.isPort(i) && !m_doc.encloses(i, m_top) &&
                (m_doc.at(i).parent < 0 || m_doc.at(i).parent == m_top) &&
                kindOf(i) != Container::None)
                m_containers << i;
        readArrowLabels();
        readCallbacks();
        for (int c : std::as_const(m_containers))
            readContainer(c);
    }

private:
    Container kindOf(int c) const
    {
        const PlantUmlDeclaration &d = m_doc.at(c);
        QString kind;
        for (int child : m_doc.children(c))
            if (kind.isEmpty())
                kind = writtenKind(m_doc.at(child).label);
        if (d.keyword == QLatin1String("frame"))
            return Container::Topic;
        if (d.keyword == QLatin1String("folder")) {
            static const QRegularExpression actionId(QStringLiteral(R"(^(pa|ra)\d*\b)"));
            const bool action = d.alias.startsWith(QLatin1String("act_")) ||
                                d.alias.startsWith(QLatin1String("a_")) ||
                                actionId.match(d.firstLine()).hasMatch() ||
                                kind == QLatin1String("action");
            return action ? Container::Action : Container::Service;
        }
        if (m_doc.children(c).isEmpty())
            return Container::None;
        if (kind == QLatin1String("srv"))
            return Container::Service;
        if (kind == QLatin1String("action"))
            return Container::Action;
        return kind == QLatin1String("msg") ? Container::Topic : Container::None;
    }

    /// The container a declaration is, or sits in; -1 when none.
    int containerOf(int i) const
    {
        for (int c : m_containers)
            if (c == i || m_doc.encloses(c, i))
                return c;
        return -1;
    }

    bool onNode(int i) const
    {
        return i == m_top || (i >= 0 && m_doc.isPort(i) && m_doc.owner(i) == m_top);
    }

    void readArrowLabels()
    {
        for (const PlantUmlArrow &a : m_doc.syntax().arrows) {
            if (a.label.isEmpty())
                continue;
            const int from = m_doc.syntax().find(a.from), to = m_doc.syntax().find(a.to);
            int node = -1, container = -1;
            if (onNode(to) && containerOf(from) >= 0) {
                node = to;
                container = containerOf(from);
            } else if (onNode(from) && containerOf(to) >= 0) {
                node = from;
                container = containerOf(to);
            }
            const QString label = a.label.simplified();
            if (node < 0) {
                m_doc.warn(a.line,
                           QStringLiteral("arrow label '%1' is not between the node and a topic "
                                          "or service; ignored")
                               .arg(label));
                continue;
            }
            if (kindOf(container) != Container::Topic) {
                m_functionLabels.insert(container, {label, a.line});
            } else if (m_doc.isPort(node) && m_doc.at(node).keyword == QLatin1String("portout")) {
                m_doc.note(a.line, QStringLiteral(
                                       "arrow label '%1' on publisher port %2 is not a callback; "
                                       "ignored")
                                       .arg(label, m_doc.at(node).alias));
            } else if (node == m_top) {
                m_looseCallbacks << Labelled{label, a.line};
            } else {
                m_arrowCallbacks.insert(node, {label, a.line});
            }
        }
    }

    void addFunction(const QString &kind, const QString &written, int line)
    {
        QString why;
        const QString f = UmlNames::functionName(written, &why);
        if (!why.isEmpty())
            m_doc.note(line, why);
        if (!f.isEmpty())
            m_doc.add(kind, f, line);
    }

    void readCallbacks()
    {
        for (int i = 0; i < m_doc.size(); ++i) {
            const PlantUmlDeclaration &p = m_doc.at(i);
            if (!m_doc.isPort(i) || m_doc.owner(i) != m_top ||
                p.keyword == QLatin1String("portout"))
                continue;
            const QString label = p.label.simplified();
            const bool portLabel = !label.isEmpty() && label != p.alias && !isPortId(label);
            if (!label.isEmpty() && !portLabel)
                m_doc.note(p.line,
                           QStringLiteral("label '%1' of port %2 names the port, not a callback")
                               .arg(label, p.alias));
            if (m_arrowCallbacks.contains(i)) {
                const Labelled &a = m_arrowCallbacks.value(i);
                if (portLabel && label != a.text)
                    m_doc.note(a.line, QStringLiteral(
                                           "callback of port %1 is '%2' on the arrow but '%3' on "
                                           "the port; the arrow's is read")
                                           .arg(p.alias, a.text, label));
                else if (!portLabel)
                    m_doc.note(a.line,
                               QStringLiteral("callback '%1' of port %2 taken from the arrow label")
                                   .arg(a.text, p.alias));
                addFunction(UmlKind::Callback, a.text, a.line);
            } else if (portLabel) {
                addFunction(UmlKind::Callback, label, p.line);
            }
        }
        for (const Labelled &l : std::as_const(m_looseCallbacks)) {
            m_doc.note(l.line,
                       QStringLiteral("callback '%1' taken from the arrow label").arg(l.text));
            addFunction(UmlKind::Callback, l.text, l.line);
        }
    }

    void readContainer(int c)
    {
        const Container kind = kindOf(c);
        const QString context = kind == Container::Topic     ? QStringLiteral("msg")
                                : kind == Container::Service ? QStringLiteral("srv")
                                                             : QStringLiteral("action");
        const QString typeKind = kind == Container::Topic     ? UmlKind::MessageType
                                 : kind == Container::Service ? UmlKind::ServiceType
                                                              : UmlKind::ActionType;
        const QString functionKind = kind == Container::Topic     ? UmlKind::Callback
                                     : kind == Container::Service ? UmlKind::ServiceFunction
                                                                  : UmlKind::ActionFunction;
        bool hasType = false, hasFunction = false;
        for (int child : m_doc.children(c)) {
            const PlantUmlDeclaration &d = m_doc.at(child);
            const QString text = d.label.simplified();
            const QString alias = d.alias;
            bool function = text.contains(QLatin1Char('(')) ||
                            alias.startsWith(QLatin1String("sf_")) ||
                            alias.startsWith(QLatin1String("af_"));
            const bool type =
                !function &&
                (text.contains(QLatin1String("::")) || text.contains(QLatin1Char('/')) ||
                 alias.startsWith(QLatin1String("st_")) || alias.startsWith(QLatin1String("at_")) ||
                 alias.startsWith(QLatin1String("t_")));
            if (!function && !type) {
                function = kind != Container::Topic && hasType;
                m_doc.note(d.line, QStringLiteral("'%1' read as %2")
                                       .arg(text, function ? QStringLiteral("the function")
                                                           : QStringLiteral("the type")));
            }
            if (function) {
                hasFunction = true;
                addFunction(functionKind, text, d.line);
                continue;
            }
            hasType = true;
            QString why;
            const QString t = UmlNames::interfaceType(text, context, &why);
            if (!why.isEmpty())
                m_doc.note(d.line, why);
            m_doc.add(typeKind, t, d.line);
        }
        const PlantUmlDeclaration &cd = m_doc.at(c);
        if (!hasType)
            m_doc.warn(cd.line, QStringLiteral("'%1' has no type").arg(cd.firstLine()));
        if (m_functionLabels.contains(c)) {
            const Labelled &l = m_functionLabels.value(c);
            if (hasFunction) {
                m_doc.note(l.line, QStringLiteral(
                                       "arrow label '%1' ignored: '%2' already names its function")
                                       .arg(l.text, cd.firstLine()));
            } else {
                m_doc.note(l.line,
                           QStringLiteral("function '%1' of '%2' taken from the arrow label")
                               .arg(l.text, cd.firstLine()));
                addFunction(functionKind, l.text, l.line);
            }
        }
    }

    const PlantUmlDocument &m_doc;
    const int m_top;
    QList<int> m_containers;
    QHash<int, Labelled> m_arrowCallbacks; ///< port declaration -> callback on an arrow label
    QHash<int, Labelled>
        m_functionLabels;             ///< service/action container -> function on an arrow label
    QList<Labelled> m_looseCallbacks; ///< callbacks on arrows that end at the node itself
};

} // namespace

void PlantUmlAcdReader::read(const PlantUmlDocument &doc, int top)
{
    AcdReader(doc, top).read();
}

} // namespace rosarch
