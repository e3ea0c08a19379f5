#include "plantuml/plantumlccdreader.h"
#include "plantuml/umlnames.h"

#include <QHash>
#include <QRegularExpression>
#include <QSet>

namespace rosarch {

namespace {

struct Part
{
    QString key; ///< the name, or the type when unnamed: what connections name the part by
    QString name;
    QString type;
    QString nameSpace; ///< from a qualified name, used when no package encloses the part
};

struct Boundary
{
    QString direction; ///< "in" or "out"
    QString type;
    QString endpoint() const { return QStringLiteral("boundary:%1/%2").arg(direction, type); }
};

struct Endpoint
{
    enum Kind
    {
        Unknown,
        Part,
        PartPort,
        Boundary,
        Topic,
        Service,
        Action,
        Other
    };
    Kind kind = Unknown;
    int part = -1; ///< declaration of the part (Part, PartPort)
    int decl = -1;
    bool isPart() const { return kind == Part || kind == PartPort; }
    bool isChannel() const { return kind == Topic || kind == Service || kind == Action; }
};

/// The type context of a port id: s1/p1 carry messages, ps1/rs1 services, pa1/ra1 actions.
QString contextOf(const QString &id)
{
    if (id.startsWith(QLatin1String("ps")) || id.startsWith(QLatin1String("rs")))
        return QStringLiteral("srv");
    if (id.startsWith(QLatin1String("pa")) || id.startsWith(QLatin1String("ra")))
        return QStringLiteral("action");
    return QStringLiteral("msg");
}

/// The index of the first ':' that is not part of a C++ "::".
qsizetype labelColon(const QString &s)
{
    for (qsizetype i = 0; i < s.size(); ++i) {
        if (s.at(i) != QLatin1Char(':'))
            continue;
        if (i + 1 < s.size() && s.at(i + 1) == QLatin1Char(':')) {
            ++i;
            continue;
        }
        return i;
    }
    return -1;
}

QString colourKind(const QString &colour)
{
    static const QHash<QString, QString> kinds = {
        {QStringLiteral("green"), QStringLiteral("publish")},
        {QStringLiteral("008000"), QStringLiteral("publish")},
        {QStringLiteral("00ff00"), QStringLiteral("publish")},
        {QStringLiteral("blue"), QStringLiteral("subscribe")},
        {QStringLiteral("0000ff"), QStringLiteral("subscribe")},
        {QStringLiteral("red"), QStringLiteral("client")},
        {QStringLiteral("ff0000"), QStringLiteral("client")},
        {QStringLiteral("purple"), QStringLiteral("server")},
        {QStringLiteral("800080"), QStringLiteral("server")}};
    return kinds.value(colour);
}

class CcdReader
{
public:
    CcdReader(const PlantUmlDocument &doc, int top) : m_doc(doc), m_top(top) {}

    void read()
    {
        if (m_top >= 0) {
            const PlantUmlDeclaration &t = m_doc.at(m_top);
            QString why;
            m_doc.diagram()->name =
                UmlNames::launchStem(t.firstLine().isEmpty() ? t.alias : t.firstLine(), &why);
            if (!why.isEmpty())
                m_doc.note(t.line, why);
        }
        for (int i = 0; i < m_doc.size(); ++i)
            if (m_doc.is(i, UmlNames::RosNodePart))
                readPart(i);
        for (int i = 0; i < m_doc.size(); ++i)
            if (m_doc.isPort(i) && m_doc.owner(i) == m_top)
                readBoundary(i);
        for (int i = 0; i < m_doc.size(); ++i)
            readChannel(i);
        for (const PlantUmlArrow &a : m_doc.syntax().arrows)
            readArrow(a);
    }

private:
    void readPart(int i)
    {
        const PlantUmlDeclaration &d = m_doc.at(i);
        const QString label =
            d.label.isEmpty() ? d.alias : QString(d.label).remove(QLatin1Char('\n'));
        Part p;
        const qsizetype colon = labelColon(label);
        if (colon < 0) {
            p.name = label.trimmed();
            m_doc.diagram()->bareParts.append({UmlNames::name(p.name), d.line});
        } else {
            p.name = label.left(colon).trimmed();
            p.type = label.mid(colon + 1).trimmed();
        }
        p.name = UmlNames::name(p.name);
        if (p.name.contains(QLatin1Char('/'))) {
            const qsizetype slash = p.name.lastIndexOf(QLatin1Char('/'));
            p.nameSpace = UmlNames::nameSpace(p.name.left(slash));
            m_doc.note(d.line, QStringLiteral("part name '%1' read as %2 in namespace %3")
                                   .arg(p.name, p.name.mid(slash + 1), p.nameSpace));
            p.name = p.name.mid(slash + 1);
        }
        if (p.name.isEmpty()) {
            QString why;
            p.type = UmlNames::launchStem(p.type, &why);
            if (!why.isEmpty())
                m_doc.note(d.line, why);
        }
        p.key = p.name.isEmpty() ? p.type : p.name;
        m_parts.insert(i, p);
        m_doc.add(UmlKind::Part, p.key, d.line);
        if (!p.type.isEmpty())
            m_doc.add(UmlKind::PartType, p.name + QLatin1Char(':') + p.type, d.line);
        m_doc.add(UmlKind::Namespace, QStringLiteral("(%1, %2)").arg(nameSpaceOf(i, p), p.key),
                  d.line);
    }

    QString nameSpaceOf(int part, const Part &p)
    {
        QStringList scopes; // innermost first
        for (int a = m_doc.at(part).parent; a >= 0; a = m_doc.at(a).parent) {
            const PlantUmlDeclaration &d = m_doc.at(a);
            const bool package =
                d.keyword == QLatin1String("package") || d.keyword == QLatin1String("namespace");
            if (!m_doc.is(a, UmlNames::NamespaceStereotype) && !package)
                continue;
            if (!m_doc.is(a, UmlNames::NamespaceStereotype) && !m_notedPackages.contains(a)) {
                m_notedPackages.insert(a);
                m_doc.note(d.line,
                           QStringLiteral("package '%1' without <<namespace>> read as a namespace")
                               .arg(d.firstLine()));
            }
            scopes << (d.firstLine().isEmpty() ? d.alias : d.firstLine());
        }
        if (scopes.isEmpty())
            return p.nameSpace.isEmpty() ? QStringLiteral("/") : p.nameSpace;
        QString ns;
        for (qsizetype k = scopes.size() - 1; k >= 0; --k) {
            const QString s = scopes.at(k).trimmed();
            ns = s.startsWith(QLatin1Char('/')) ? s : ns + QLatin1Char('/') + s;
        }
        return UmlNames::nameSpace(ns);
    }

    void readBoundary(int i)
    {
        const PlantUmlDeclaration &d = m_doc.at(i);
        QString id, type;
        const QString text = d.label.simplified();
        // "s1 / pkg::msg::T", also with the space on one side only ("s1 /pkg::msg::T").
        static const QRegularExpression idSlashType(
            QStringLiteral(R"(^(\w+)(?: /\s*|\s*/ )(.+)$)"));
        if (const auto m = idSlashType.match(text); m.hasMatch()) {
            id = m.captured(1);
            type = m.captured(2).simplified();
        } else if (d.label.contains(QLatin1Char('\n')) || text.contains(QLatin1Char(' '))) {
            id = text.section(QLatin1Char(' '), 0, 0);
            type = text.section(QLatin1Char(' '), 1);
        } else if (text.contains(QLatin1String("::")) || text.count(QLatin1Char('/')) >= 2) {
            id = d.alias.section(QLatin1Char('_'), -1);
            type = text;
        } else {
            id = text;
        }
        Boundary b;
        if (d.keyword == QLatin1String("port")) {
            static const QRegularExpression input(QStringLiteral(R"(^(s|ps|pa)\d*$)"));
            b.direction = input.match(id).hasMatch() ? QStringLiteral("in") : QStringLiteral("out");
            m_doc.note(d.line, QStringLiteral("port %1 read as direction %2").arg(id, b.direction));
        } else {
            b.direction =
                d.keyword == QLatin1String("portin") ? QStringLiteral("in") : QStringLiteral("out");
        }
        QString why;
        b.type = UmlNames::interfaceType(type, contextOf(id), &why);
        if (!why.isEmpty())
            m_doc.note(d.line, why);
        if (b.type.isEmpty()) {
            b.type = QStringLiteral("?");
            m_doc.warn(d.line, QStringLiteral("boundary port '%1' has no type").arg(text));
        }
        m_boundaries.insert(i, b);
        m_doc.add(UmlKind::BoundaryPort, QStringLiteral("(%1, %2)").arg(b.direction, b.type),
                  d.line);
    }

    void readChannel(int i)
    {
        const PlantUmlDeclaration &d = m_doc.at(i);
        const QString name = UmlNames::name(d.firstLine().isEmpty() ? d.alias : d.firstLine());
        if (d.keyword == QLatin1String("queue")) {
            m_channels.insert(i, Endpoint::Topic);
            m_doc.add(UmlKind::Topic, name, d.line);
        } else if (d.keyword == QLatin1String("circle") ||
                   d.keyword == QLatin1String("interface")) {
            const bool action = m_doc.is(i, UmlNames::ActionStereotype);
            if (!action && !m_doc.is(i, UmlNames::ServiceStereotype))
                m_doc.note(d.line, QStringLiteral("%1 '%2' without <<Service>> read as a service")
                                       .arg(d.keyword, name));
            m_channels.insert(i, action ? Endpoint::Action : Endpoint::Service);
            m_doc.add(action ? UmlKind::Action : UmlKind::Service, name, d.line);
        }
    }

    Endpoint resolve(const QString &written) const
    {
        Endpoint e;
        e.decl = m_doc.syntax().find(written);
        if (e.decl < 0)
            return e;
        if (m_parts.contains(e.decl)) {
            e.kind = Endpoint::Part;
            e.part = e.decl;
        } else if (m_boundaries.contains(e.decl)) {
            e.kind = Endpoint::Boundary;
        } else if (m_channels.contains(e.decl)) {
            e.kind = m_channels.value(e.decl);
        } else if (m_doc.isPort(e.decl) && m_parts.contains(m_doc.owner(e.decl))) {
            e.kind = Endpoint::PartPort;
            e.part = m_doc.owner(e.decl);
        } else {
            e.kind = Endpoint::Other;
        }
        return e;
    }

    QString channelName(const Endpoint &e) const
    {
        const PlantUmlDeclaration &d = m_doc.at(e.decl);
        return UmlNames::name(d.firstLine().isEmpty() ? d.alias : d.firstLine());
    }

    /// The kind the endpoint shapes give: part -> queue publishes, a server port serves, ...
    QString shapeKind(const Endpoint &part, const Endpoint &channel, bool partFirst,
                      bool directed) const
    {
        const PlantUmlDeclaration *port =
            part.kind == Endpoint::PartPort ? &m_doc.at(part.decl) : nullptr;
        if (channel.kind == Endpoint::Topic) {
            if (directed)
                return partFirst ? QStringLiteral("publish") : QStringLiteral("subscribe");
            return port && port->keyword == QLatin1String("portin") ? QStringLiteral("subscribe")
                                                                    : QStringLiteral("publish");
        }
        if (!port)
            return QStringLiteral("client");
        const QString id = port->firstLine();
        if (id.startsWith(QLatin1String("ps")) || id.startsWith(QLatin1String("pa")))
            return QStringLiteral("server");
        if (id.startsWith(QLatin1String("rs")) || id.startsWith(QLatin1String("ra")))
            return QStringLiteral("client");
        return port->keyword == QLatin1String("portin") ? QStringLiteral("server")
                                                        : QStringLiteral("client");
    }

    void readArrow(const PlantUmlArrow &a)
    {
        const Endpoint from = resolve(a.from), to = resolve(a.to);
        for (const auto &[e, written] : {std::pair{from, a.from}, std::pair{to, a.to}}) {
            if (e.kind == Endpoint::Unknown) {
                m_doc.warn(
                    a.line,
                    QStringLiteral("arrow end '%1' is not declared; arrow ignored").arg(written));
                return;
            }
        }
        if (from.kind == Endpoint::Boundary || to.kind == Endpoint::Boundary) {
            const Endpoint &b = from.kind == Endpoint::Boundary ? from : to;
            const Endpoint &other = from.kind == Endpoint::Boundary ? to : from;
            if (other.kind == Endpoint::Boundary || other.kind == Endpoint::Other) {
                m_doc.warn(a.line, QStringLiteral("arrow %1 -> %2 is not a delegation; ignored")
                                       .arg(a.from, a.to));
                return;
            }
            const Boundary &boundary = m_boundaries.value(b.decl);
            const QString inner =
                other.isPart() ? m_parts.value(other.part).key : channelName(other);
            add(a.line,
                boundary.direction == QLatin1String("in")
                    ? QStringLiteral("delegation %1 -> %2").arg(boundary.endpoint(), inner)
                    : QStringLiteral("delegation %1 -> %2").arg(inner, boundary.endpoint()));
            return;
        }
        const QString colour = colourKind(a.color);
        if (!(from.isPart() && to.isChannel()) && !(from.isChannel() && to.isPart())) {
            if (from.isPart() && to.isPart()) {
                add(a.line, QStringLiteral("%1 %2 -> %3")
                                .arg(colour.isEmpty() ? QStringLiteral("link") : colour,
                                     m_parts.value(from.part).key, m_parts.value(to.part).key));
                return;
            }
            m_doc.warn(
                a.line,
                QStringLiteral("arrow %1 -> %2 does not connect a part with a topic, service or "
                               "boundary port; ignored")
                    .arg(a.from, a.to));
            return;
        }
        const Endpoint &part = from.isPart() ? from : to;
        const Endpoint &channel = from.isPart() ? to : from;
        const QString shape = shapeKind(part, channel, from.isPart(), a.directed);
        QString kind = colour;
        if (kind.isEmpty()) {
            kind = shape;
            m_doc.note(
                a.line,
                QStringLiteral("connection kind '%1' inferred from the arrow ends").arg(kind));
        } else if (kind != shape) {
            m_doc.note(
                a.line,
                QStringLiteral("colour says '%1' but the arrow ends say '%2'; the colour is read")
                    .arg(kind, shape));
        }
        const QString p = m_parts.value(part.part).key, c = channelName(channel);
        add(a.line, kind == QLatin1String("subscribe")
                        ? QStringLiteral("subscribe %1 -> %2").arg(c, p)
                        : QStringLiteral("%1 %2 -> %3").arg(kind, p, c));
    }

    void add(int line, const QString &value) const { m_doc.add(UmlKind::Connection, value, line); }

    const PlantUmlDocument &m_doc;
    const int m_top;
    QHash<int, Part> m_parts;              ///< part declaration -> part
    QHash<int, Boundary> m_boundaries;     ///< boundary port declaration -> port
    QHash<int, Endpoint::Kind> m_channels; ///< queue / circle declaration -> topic, service, action
    QSet<int> m_notedPackages;
};

} // namespace

void PlantUmlCcdReader::read(const PlantUmlDocument &doc, int top)
{
    CcdReader(doc, top).read();
}

} // namespace rosarch
