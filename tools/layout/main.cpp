// rosarch-layout: reads a DOT graph on stdin, runs Graphviz `dot` layout in this process and
// writes the positioned graph to stdout as JSON, in Graphviz coordinates (points, y up):
//
//   {"bb":[llx,lly,urx,ury],
//    "nodes":[{"name":"n1","x":..,"y":..,"width":..,"height":..}],
//    "clusters":[{"name":"cluster_1","bb":[..],"label":[x,y,w,h]}],       // label optional
//    "edges":[{"id":"e1","tail":"n1","head":"n2",
//              "splines":[{"points":[[x,y],..],"start":[x,y],"end":[x,y]}], // cubic Bézier
//              "label":[x,y]}]}                                             // optional
//
// Exit codes: 0 laid out, 2 unreadable DOT, 3 layout failed, 4 no layout engine.
// Graphviz may abort() or loop on some inputs; the caller runs this with a timeout.
//
// Graphviz 2.4x's network simplex (rank and x positions) recurses once per node of its
// auxiliary graph: a composite of a few hundred parts in one rank went ~175,000 frames deep and
// overflowed the default 8 MB stack (SIGSEGV). The layout runs on a thread with a big stack;
// the pages are only committed as the recursion touches them.
#include <graphviz/graphviz_version.h>
#include <graphviz/gvc.h>

#include <pthread.h>

#include <clocale>
#include <cstdio>
#include <cstring>
#include <string>

extern "C" {
extern gvplugin_library_t gvplugin_dot_layout_LTX_library;
}

namespace {

// The dot layout engine, registered from this binary rather than loaded through the plugin
// configuration file, which a machine with only the -dev package may not have.
lt_symlist_t builtins[] = {
    {"gvplugin_dot_layout_LTX_library", &gvplugin_dot_layout_LTX_library},
    {nullptr, nullptr},
};

void writeString(std::string &out, const char *s)
{
    out += '"';
    for (const char *p = s ? s : ""; *p; ++p) {
        const unsigned char c = static_cast<unsigned char>(*p);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += static_cast<char>(c);
        }
    }
    out += '"';
}

void writeNumber(std::string &out, double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    out += buf;
}

void writePoint(std::string &out, pointf p)
{
    out += '[';
    writeNumber(out, p.x);
    out += ',';
    writeNumber(out, p.y);
    out += ']';
}

void writeBox(std::string &out, boxf b)
{
    out += '[';
    writeNumber(out, b.LL.x);
    out += ',';
    writeNumber(out, b.LL.y);
    out += ',';
    writeNumber(out, b.UR.x);
    out += ',';
    writeNumber(out, b.UR.y);
    out += ']';
}

void writeClusters(std::string &out, Agraph_t *g, bool &first)
{
    for (int i = 1; i <= GD_n_cluster(g); ++i) {
        Agraph_t *sg = GD_clust(g)[i];
        out += first ? "\n  " : ",\n  ";
        first = false;
        out += "{\"name\":";
        writeString(out, agnameof(sg));
        out += ",\"bb\":";
        writeBox(out, GD_bb(sg));
        if (textlabel_t *label = GD_label(sg); label && label->set) {
            out += ",\"label\":[";
            writeNumber(out, label->pos.x);
            out += ',';
            writeNumber(out, label->pos.y);
            out += ',';
            writeNumber(out, label->dimen.x);
            out += ',';
            writeNumber(out, label->dimen.y);
            out += ']';
        }
        out += '}';
        writeClusters(out, sg, first);
    }
}

void writeEdge(std::string &out, Agedge_t *e)
{
    out += "{\"id\":";
    writeString(out, agget(e, const_cast<char *>("id")));
    out += ",\"tail\":";
    writeString(out, agnameof(agtail(e)));
    out += ",\"head\":";
    writeString(out, agnameof(aghead(e)));
    out += ",\"splines\":[";
    if (splines *spl = ED_spl(e)) {
        for (int i = 0; i < spl->size; ++i) {
            const bezier &bz = spl->list[i];
            out += i ? ",{\"points\":[" : "{\"points\":[";
            for (int j = 0; j < bz.size; ++j) {
                if (j)
                    out += ',';
                writePoint(out, bz.list[j]);
            }
            out += ']';
            if (bz.sflag) {
                out += ",\"start\":";
                writePoint(out, bz.sp);
            }
            if (bz.eflag) {
                out += ",\"end\":";
                writePoint(out, bz.ep);
            }
            out += '}';
        }
    }
    out += ']';
    if (textlabel_t *label = ED_label(e); label && label->set) {
        out += ",\"label\":";
        writePoint(out, label->pos);
    }
    out += '}';
}

std::string toJson(Agraph_t *g)
{
    std::string out = "{\"bb\":";
    writeBox(out, GD_bb(g));
    out += ",\n\"nodes\":[";
    bool first = true;
    for (Agnode_t *n = agfstnode(g); n; n = agnxtnode(g, n)) {
        out += first ? "\n  " : ",\n  ";
        first = false;
        out += "{\"name\":";
        writeString(out, agnameof(n));
        out += ",\"x\":";
        writeNumber(out, ND_coord(n).x);
        out += ",\"y\":";
        writeNumber(out, ND_coord(n).y);
        out += ",\"width\":";
        writeNumber(out, ND_width(n) * 72.0);
        out += ",\"height\":";
        writeNumber(out, ND_height(n) * 72.0);
        out += '}';
    }
    out += "],\n\"clusters\":[";
    first = true;
    writeClusters(out, g, first);
    out += "],\n\"edges\":[";
    first = true;
    for (Agnode_t *n = agfstnode(g); n; n = agnxtnode(g, n)) {
        for (Agedge_t *e = agfstout(g, n); e; e = agnxtout(g, e)) {
            out += first ? "\n  " : ",\n  ";
            first = false;
            writeEdge(out, e);
        }
    }
    out += "]}\n";
    return out;
}

/// Reads DOT from stdin, lays it out and writes the JSON; the process's exit code.
int run()
{
    GVC_t *gvc = gvContextPlugins(builtins, 0);
    Agraph_t *g = agread(stdin, nullptr);
    if (!g) {
        std::fprintf(stderr, "rosarch-layout: the input is not a DOT graph\n");
        gvFreeContext(gvc);
        return 2;
    }
    if (gvLayout(gvc, g, "dot") != 0) {
        std::fprintf(stderr, "rosarch-layout: the dot layout failed\n");
        agclose(g);
        gvFreeContext(gvc);
        return 3;
    }
    const std::string json = toJson(g);
    std::fwrite(json.data(), 1, json.size(), stdout);
    std::fflush(stdout);
    gvFreeLayout(gvc, g);
    agclose(g);
    return gvFreeContext(gvc) == 0 ? 0 : 3;
}

void *runThread(void *exitCode)
{
    *static_cast<int *>(exitCode) = run();
    return nullptr;
}

} // namespace

int main(int argc, char **argv)
{
    std::setlocale(LC_NUMERIC, "C"); // "%.2f" must write a decimal point
    if (argc > 1 && std::strcmp(argv[1], "--version") == 0) {
        std::printf("rosarch-layout (Graphviz %s)\n", PACKAGE_VERSION);
        return 0;
    }
    constexpr size_t kStackBytes = size_t(1) << 30; // 1 GB of address space, see above
    int exitCode = 3;
    pthread_attr_t attributes;
    pthread_t thread;
    if (pthread_attr_init(&attributes) != 0 ||
        pthread_attr_setstacksize(&attributes, kStackBytes) != 0 ||
        pthread_create(&thread, &attributes, &runThread, &exitCode) != 0)
        return run(); // no big stack to be had: the default one does for most diagrams
    pthread_attr_destroy(&attributes);
    pthread_join(thread, nullptr);
    return exitCode;
}
