#include "interfaces/interfacemodel.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>

#include <algorithm>
#include <mutex>

// Resources of a static library must be registered explicitly; outside any namespace.
static void initInterfaceModelResources()
{
    static std::once_flag once;
    std::call_once(once, [] { Q_INIT_RESOURCE(interfaces); });
}

namespace rosarch {

namespace {

QStringList strings(const QJsonValue &v)
{
    QStringList out;
    for (const QJsonValue &s : v.toArray())
        if (s.isString() && !s.toString().isEmpty())
            out << s.toString();
    return out;
}

} // namespace

bool InterfaceModel::fromJson(const QJsonObject &o, InterfaceModel *model, QString *error)
{
    InterfaceModel m;
    m.name = o.value(QLatin1String("name")).toString();
    m.description = o.value(QLatin1String("description")).toString();
    m.package = o.value(QLatin1String("package")).toString();
    if (m.name.isEmpty() || m.package.isEmpty()) {
        *error = QStringLiteral("a model needs a name and a package");
        return false;
    }
    if (const QStringList own = strings(o.value(QLatin1String("executables"))); !own.isEmpty())
        m.executables.append({m.package, own});
    for (const QJsonValue &also : o.value(QLatin1String("also")).toArray()) {
        const QJsonObject a = also.toObject();
        const QString package = a.value(QLatin1String("package")).toString();
        const QStringList exes = strings(a.value(QLatin1String("executables")));
        if (package.isEmpty() || exes.isEmpty()) {
            *error =
                QStringLiteral("%1: an 'also' entry needs a package and executables").arg(m.name);
            return false;
        }
        m.executables.append({package, exes});
    }
    m.launchFiles = strings(o.value(QLatin1String("launch_files")));
    const QJsonObject config = o.value(QLatin1String("config")).toObject();
    m.configArgument = config.value(QLatin1String("argument")).toString();
    m.configFormat = config.value(QLatin1String("format")).toString();
    const QJsonObject types = config.value(QLatin1String("types")).toObject();
    for (auto it = types.begin(); it != types.end(); ++it)
        m.configTypes.append({it.key(), it.value().toString()});
    m.namespaceArgument = o.value(QLatin1String("namespace_argument")).toString();
    if (m.executables.isEmpty() && m.launchFiles.isEmpty()) {
        *error = QStringLiteral("%1: a model names executables or launch files").arg(m.name);
        return false;
    }
    for (const QJsonValue &p : o.value(QLatin1String("ports")).toArray()) {
        const QJsonObject po = p.toObject();
        ModelPort port;
        port.name = po.value(QLatin1String("name")).toString();
        port.type = po.value(QLatin1String("type")).toString();
        if (!portKindFromName(po.value(QLatin1String("kind")).toString(), &port.kind) ||
            port.name.isEmpty() || port.type.count(QLatin1Char('/')) != 2) {
            *error = QStringLiteral("%1: a port needs a known kind, a name and a type pkg/msg/T")
                         .arg(m.name);
            return false;
        }
        m.ports.append(port);
    }
    *model = m;
    return true;
}

QList<Port> InterfaceModel::portsAt(const Evidence &evidence) const
{
    QList<Port> out;
    for (const ModelPort &mp : ports) {
        Port p;
        p.id = QStringLiteral("m%1").arg(out.size() + 1);
        p.kind = mp.kind;
        p.name = mp.name;
        p.type = mp.type;
        p.via = QStringLiteral("interface model %1").arg(name);
        p.evidence = evidence;
        out.append(p);
    }
    return out;
}

QList<Port> InterfaceModel::portsFromConfig(const QByteArray &text, const QString &file,
                                            int firstId) const
{
    QList<Port> out;
    if (configFormat != QLatin1String("rviz"))
        return out;
    // An RViz configuration is YAML whose displays say `Class: <plugin>` and, below, one or
    // more `<...> Topic:` maps with a `Value:` (the topic); the tools under `Tools:` publish
    // theirs. Indentation says what belongs to what; a line is read on its own, so a broken
    // file gives what it has.
    QString displayClass;
    int classIndent = -1;
    int toolsIndent = -1; ///< inside `Tools:` (the tools publish what their Topic names)
    int topicIndent = -1; ///< the indentation of the open `... Topic:` key, -1 when none
    QString topicKey;
    const QList<QByteArray> lines = text.split('\n');
    for (qsizetype i = 0; i < lines.size() && out.size() < kMaxConfigPorts; ++i) {
        const QString line = QString::fromUtf8(lines.at(i));
        QString trimmed = line.trimmed();
        if (trimmed.startsWith(QLatin1String("- ")))
            trimmed = trimmed.mid(2).trimmed(); // a list item's first key
        if (trimmed.isEmpty() || trimmed.startsWith(QLatin1Char('#')))
            continue;
        int indent = 0;
        while (indent < line.size() && (line.at(indent) == u' ' || line.at(indent) == u'-'))
            ++indent;
        if (topicIndent >= 0 && indent <= topicIndent)
            topicIndent = -1;
        if (toolsIndent >= 0 && indent <= toolsIndent && !line.trimmed().startsWith(u'-'))
            toolsIndent = -1;
        if (trimmed == QLatin1String("Tools:"))
            toolsIndent = indent;
        if (classIndent >= 0 && indent < classIndent) {
            classIndent = -1;
            displayClass.clear();
        }
        if (trimmed.startsWith(QLatin1String("Class:"))) {
            displayClass = trimmed.mid(6).trimmed();
            classIndent = indent;
        } else if (trimmed.endsWith(QLatin1String("Topic:"))) {
            topicIndent = indent;
            topicKey = trimmed.chopped(1);
        } else if (topicIndent >= 0 && trimmed.startsWith(QLatin1String("Value:"))) {
            QString topic = trimmed.mid(6).trimmed();
            if (topic.size() >= 2 && (topic.front() == u'"' || topic.front() == u'\'') &&
                topic.back() == topic.front())
                topic = topic.mid(1, topic.size() - 2);
            topicIndent = -1;
            if (topic.isEmpty() || topic.contains(QLatin1Char(' ')))
                continue;
            Port p;
            p.id = QStringLiteral("m%1").arg(firstId + out.size());
            p.kind = toolsIndent >= 0 ? PortKind::Publisher : PortKind::Subscriber;
            p.name = topic;
            // "Update Topic" of a map display carries the updates, not the map.
            if (topicKey == QLatin1String("Topic"))
                for (const auto &[cls, type] : configTypes)
                    if (cls == displayClass)
                        p.type = type;
            p.via = QStringLiteral("interface model %1 (%2)").arg(name, topicKey.toLower());
            p.evidence = Evidence{file, int(i) + 1, indent + 1, int(i) + 1, int(line.size()) + 1};
            out.append(p);
        }
    }
    return out;
}

const InterfaceModels &InterfaceModels::builtIn()
{
    static const InterfaceModels models = [] {
        initInterfaceModelResources();
        return fromFolder(QStringLiteral(":/interfaces/models"));
    }();
    return models;
}

InterfaceModels InterfaceModels::fromFolder(const QString &folder, QStringList *problems)
{
    InterfaceModels out;
    const QDir dir(folder);
    for (const QString &file : dir.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name)) {
        QFile f(dir.filePath(file));
        QJsonParseError parse;
        const QJsonDocument doc = f.open(QIODevice::ReadOnly)
                                      ? QJsonDocument::fromJson(f.readAll(), &parse)
                                      : QJsonDocument();
        InterfaceModel m;
        QString error;
        if (!doc.isObject())
            error = QStringLiteral("not a JSON object");
        else if (InterfaceModel::fromJson(doc.object(), &m, &error))
            out.m_models.append(m);
        if (!error.isEmpty() && problems)
            *problems << QStringLiteral("%1: %2").arg(file, error);
    }
    std::sort(out.m_models.begin(), out.m_models.end(),
              [](const InterfaceModel &a, const InterfaceModel &b) { return a.name < b.name; });
    return out;
}

const InterfaceModel *InterfaceModels::executable(const QString &package,
                                                  const QString &executable) const
{
    for (const InterfaceModel &m : m_models)
        for (const auto &[pkg, exes] : m.executables)
            if (pkg == package && exes.contains(executable))
                return &m;
    return nullptr;
}

const InterfaceModel *InterfaceModels::launchFile(const QString &package, const QString &file) const
{
    QString relative = file;
    while (relative.startsWith(QLatin1Char('/')))
        relative.remove(0, 1);
    for (const InterfaceModel &m : m_models)
        if (m.package == package && m.launchFiles.contains(relative))
            return &m;
    return nullptr;
}

} // namespace rosarch
