#include "core/composition.h"

#include <QSet>

namespace rosarch {

namespace {
template <typename T> const T *findById(const QList<T> &list, const QString &id)
{
    for (const T &item : list)
        if (item.id == id)
            return &item;
    return nullptr;
}
} // namespace

bool BoundaryPort::isInput() const
{
    return isInputPort(kind);
}

const RosNodePart *Composite::part(const QString &id) const
{
    return findById(parts, id);
}

const Channel *Composite::channel(const QString &id) const
{
    return findById(channels, id);
}

const BoundaryPort *Composite::boundaryPort(const QString &id) const
{
    return findById(boundary, id);
}

const Composite *Architecture::composite(const QString &instanceId) const
{
    for (const Composite &c : composites)
        if (c.instanceId == instanceId)
            return &c;
    return nullptr;
}

QList<const Composite *> Architecture::representatives() const
{
    QList<const Composite *> out;
    QSet<QString> seen;
    auto add = [&](const Composite &c) {
        const QString key = c.file.isEmpty() ? c.stem : c.file;
        if (seen.contains(key))
            return;
        seen.insert(key);
        out.append(&c);
    };
    for (const Composite &c : classifiers)
        add(c);
    // A workspace file without a classifier (its run was skipped or over budget) is drawn as
    // first included; without classifiers at all, every file is.
    for (const Composite &c : composites)
        if (classifiers.isEmpty() || !c.file.isEmpty())
            add(c);
    return out;
}

QString connectionKindName(Connection::Kind kind)
{
    switch (kind) {
    case Connection::Kind::Publish:
        return QStringLiteral("publish");
    case Connection::Kind::Subscribe:
        return QStringLiteral("subscribe");
    case Connection::Kind::Client:
        return QStringLiteral("client");
    case Connection::Kind::Server:
        return QStringLiteral("server");
    case Connection::Kind::DelegationIn:
        return QStringLiteral("delegation_in");
    case Connection::Kind::DelegationOut:
        return QStringLiteral("delegation_out");
    }
    return {};
}

QString channelKindName(Channel::Kind kind)
{
    switch (kind) {
    case Channel::Kind::Topic:
        return QStringLiteral("topic");
    case Channel::Kind::Service:
        return QStringLiteral("service");
    case Channel::Kind::Action:
        return QStringLiteral("action");
    }
    return {};
}

} // namespace rosarch
