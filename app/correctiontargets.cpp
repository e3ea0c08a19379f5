#include "app/correctiontargets.h"
#include "app/correctionlookup.h"
#include "document/document.h"

namespace rosarch {

namespace {

using Kind = CorrectionElement::Kind;
using namespace CorrectionLookup;

} // namespace

CorrectionTargets::CorrectionTargets(Document *document, QObject *parent)
    : QObject(parent), m_document(document)
{
    // Connected before the inspector's own handler, so the inspector reads the new index.
    connect(document, &Document::changed, this, [this] { m_index.reset(); });
}

const CorrectionIndex &CorrectionTargets::index()
{
    if (!m_index)
        m_index = CorrectionIndex(*m_document);
    return *m_index;
}

QString CorrectionTargets::keyOf(const QString &id)
{
    if (StableKeys::isChannelKey(id))
        return id;
    if (index().isEmpty()) // no corrections: the model as recovered is the corrected one
        return m_document->session()->keyOf(id);
    return index().keyOf(id);
}

bool CorrectionTargets::keysAtHand(const QString &id)
{
    return StableKeys::isChannelKey(id) || !index().isEmpty() || m_document->session()->keysReady();
}

bool CorrectionTargets::isRemoved(const CorrectionElement &element)
{
    if (element.kind != Kind::Class && element.kind != Kind::Port && element.kind != Kind::Instance)
        return false;
    return !index().removedBy(element.id).isEmpty();
}

QString CorrectionTargets::nameOf(const CorrectionElement &e)
{
    const Recovery &now = m_document->accepted();
    switch (e.kind) {
    case Kind::Class:
        if (const AtomicNode *n = now.nodes.node(e.id))
            return n->className;
        if (const AtomicNode *n = m_document->atomicNodes().node(e.id))
            return n->className;
        return {};
    case Kind::Port:
        if (const Port *p = findPort(now.nodes, e.id))
            return portName(*p);
        if (const Port *p = findPort(m_document->atomicNodes(), e.id))
            return portName(*p);
        return {};
    case Kind::Instance:
    case Kind::Connection:
        if (const NodeInstance *n = now.launch.node(e.id))
            return instanceName(*n);
        if (const NodeInstance *n = m_document->launchDependencies().node(e.id))
            return instanceName(*n);
        return {};
    case Kind::LaunchFile:
        if (const LaunchFileInstance *lf = now.launch.instance(e.id))
            return lf->file.isEmpty() ? lf->type : lf->file.section(u'/', -1);
        return {};
    case Kind::Channel:
        return e.id.section(u':', 1);
    case Kind::None:
        break;
    }
    return {};
}

} // namespace rosarch
