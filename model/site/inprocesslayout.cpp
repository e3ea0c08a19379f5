#include "site/inprocesslayout.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QMutex>
#include <QThread>

#include <graphviz/graphviz_version.h>
#include <graphviz/gvc.h>

#include <clocale>
#include <cstdio>
#include <memory>
#include <string>

extern "C" {
extern gvplugin_library_t gvplugin_dot_layout_LTX_library;
}

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::InProcessLayout", text);
}

// The dot engine registered from this library, not through Graphviz's plugin configuration
// file, which a machine with only the -dev package may lack (as in tools/layout).
lt_symlist_t builtins[] = {
    {"gvplugin_dot_layout_LTX_library", &gvplugin_dot_layout_LTX_library},
    {nullptr, nullptr},
};

// The positioned graph as JSON in the layout helper's format (tools/layout/main.cpp), so that
// GraphLayout::parseGeometry maps it back to the graph's ids exactly as for the GUI.
class JsonOut
{
public:
    std::string text;

    void number(double v)
    {
        char buf[32];
        // "%.2f" needs the C locale's decimal point; the caller sets it (setlocale is global).
        std::snprintf(buf, sizeof buf, "%.2f", v);
        text += buf;
    }
    void point(pointf p)
    {
        text += '[';
        number(p.x);
        text += ',';
        number(p.y);
        text += ']';
    }
    void box(boxf b)
    {
        text += '[';
        number(b.LL.x);
        text += ',';
        number(b.LL.y);
        text += ',';
        number(b.UR.x);
        text += ',';
        number(b.UR.y);
        text += ']';
    }
    void string(const char *s)
    {
        // Our DOT names are "n12", "cluster_3" and "e7": nothing to escape.
        text += '"';
        text += s ? s : "";
        text += '"';
    }
    void clusters(Agraph_t *g, bool &first)
    {
        for (int i = 1; i <= GD_n_cluster(g); ++i) {
            Agraph_t *sg = GD_clust(g)[i];
            text += first ? "{\"name\":" : ",{\"name\":";
            first = false;
            string(agnameof(sg));
            text += ",\"bb\":";
            box(GD_bb(sg));
            if (textlabel_t *label = GD_label(sg); label && label->set) {
                text += ",\"label\":[";
                number(label->pos.x);
                text += ',';
                number(label->pos.y);
                text += ',';
                number(label->dimen.x);
                text += ',';
                number(label->dimen.y);
                text += ']';
            }
            text += '}';
            clusters(sg, first);
        }
    }
    void edge(Agedge_t *e)
    {
        text += "{\"id\":";
        string(agget(e, const_cast<char *>("id")));
        text += ",\"splines\":[";
        if (splines *spl = ED_spl(e)) {
            for (int i = 0; i < spl->size; ++i) {
                const bezier &bz = spl->list[i];
                text += i ? ",{\"points\":[" : "{\"points\":[";
                for (int j = 0; j < bz.size; ++j) {
                    if (j)
                        text += ',';
                    point(bz.list[j]);
                }
                text += ']';
                if (bz.sflag) {
                    text += ",\"start\":";
                    point(bz.sp);
                }
                if (bz.eflag) {
                    text += ",\"end\":";
                    point(bz.ep);
                }
                text += '}';
            }
        }
        text += "]}";
    }
    void graph(Agraph_t *g)
    {
        text += "{\"bb\":";
        box(GD_bb(g));
        text += ",\"nodes\":[";
        bool first = true;
        for (Agnode_t *n = agfstnode(g); n; n = agnxtnode(g, n)) {
            text += first ? "{\"name\":" : ",{\"name\":";
            first = false;
            string(agnameof(n));
            text += ",\"x\":";
            number(ND_coord(n).x);
            text += ",\"y\":";
            number(ND_coord(n).y);
            text += ",\"width\":";
            number(ND_width(n) * 72.0);
            text += ",\"height\":";
            number(ND_height(n) * 72.0);
            text += '}';
        }
        text += "],\"clusters\":[";
        first = true;
        clusters(g, first);
        text += "],\"edges\":[";
        first = true;
        for (Agnode_t *n = agfstnode(g); n; n = agnxtnode(g, n))
            for (Agedge_t *e = agfstout(g, n); e; e = agnxtout(g, e)) {
                if (!first)
                    text += ',';
                first = false;
                edge(e);
            }
        text += "]}";
    }
};

/// Lays `dot` out; the JSON, or "" with `error`.
std::string run(const QByteArray &dot, QString *error)
{
    GVC_t *gvc = gvContextPlugins(builtins, 0);
    Agraph_t *g = agmemread(dot.constData());
    if (!g) {
        *error = tr("Graphviz could not read the diagram.");
        gvFreeContext(gvc);
        return {};
    }
    std::string json;
    if (gvLayout(gvc, g, "dot") != 0) {
        *error = tr("Graphviz could not lay out the diagram.");
    } else {
        JsonOut out;
        out.graph(g);
        json = std::move(out.text);
        gvFreeLayout(gvc, g);
    }
    agclose(g);
    gvFreeContext(gvc);
    return json;
}

QMutex &graphvizMutex()
{
    static QMutex mutex;
    return mutex;
}

} // namespace

LayoutResult InProcessLayout::layout(const LayoutGraph &graph)
{
    LayoutResult result;
    QElapsedTimer clock;
    clock.start();
    const QByteArray dot = GraphLayout::toDot(graph).toUtf8();
    std::string json;
    QString error;
    {
        const QMutexLocker lock(&graphvizMutex());
        const std::string numeric = std::setlocale(LC_NUMERIC, nullptr);
        std::setlocale(LC_NUMERIC, "C");
        std::unique_ptr<QThread> thread(QThread::create([&] { json = run(dot, &error); }));
        thread->setStackSize(1U << 30); // address space only: pages are committed as used
        thread->start();
        thread->wait();
        std::setlocale(LC_NUMERIC, numeric.c_str());
    }
    result.elapsedMs = clock.elapsed();
    if (!error.isEmpty()) {
        result.error = error;
        return result;
    }
    result.ok = GraphLayout::parseGeometry(QByteArray::fromStdString(json), graph, &result.geometry,
                                           &result.error);
    return result;
}

QString InProcessLayout::graphvizVersion()
{
    return QStringLiteral(PACKAGE_VERSION);
}

} // namespace rosarch
