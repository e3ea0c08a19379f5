#include "interfacemodel.h"

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
