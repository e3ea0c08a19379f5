#include "core/diagnostickind.h"

namespace rosarch {

namespace {

DiagnosticKind kind(const char *code, const char *title, const char *help, const char *level)
{
    return {QString::fromLatin1(code), QString::fromUtf8(title), QString::fromUtf8(help),
            QString::fromLatin1(level)};
}

} // namespace

const QList<DiagnosticKind> &DiagnosticKind::all()
{
    static const QList<DiagnosticKind> kinds = {
        // Architecture checks (stage 3), per system started from an entry point: a launch file
        // no other file includes under any condition. A launch file that starts one node is a
        // building block, and its open ports are not reported.
        kind("topic-unpublished", "Subscription that nobody publishes",
             "A node subscribes to a topic that no node started from the same entry point "
             "publishes, so its callback never runs in that system, and there is evidence of a "
             "mistake, which the message gives: another launch file remaps this port where it "
             "starts the same node class and this one does not, or a published name is a "
             "misspelling of it or the same name in a namespace pushed once too often or not at "
             "all. (An open port without such evidence is the system's boundary, no finding.) "
             "Add the remap or fix the name; when the data really comes from outside, accept "
             "the topic as an expected external input (X): the project records it for every "
             "system.",
             "warning"),
        kind("topic-unheard", "Publisher that nobody subscribes to",
             "A node publishes a topic that no node of the same system subscribes to, and there "
             "is evidence of a mistake, which the message gives: another launch file wires this "
             "port to a name that this system hears and this one does not, or a subscribed name "
             "is a misspelling of it or the same name in another namespace. Outputs meant for "
             "tools (debug, visualisation, diagnostics, processing time, see "
             "interfaces/observability.json) and topics an RViz configuration displays are "
             "never reported. Add the remap or fix the name, or, when something outside reads "
             "it, accept it as an expected external output (X).",
             "note"),
        kind("type-mismatch", "One name, several interface types",
             "The publishers, subscriptions, servers or clients of one name use different "
             "message, service or action types; ROS 2 will not connect them. Make the types "
             "agree, or give one side another name.",
             "warning"),
        kind("duplicate-server", "Several servers for one service or action",
             "More than one node of a system serves the same service or action; which one "
             "answers a request is undefined. Nodes that run only because a launch condition "
             "could not be decided may be alternatives and are not counted. Rename or remap one "
             "of them, or start only one.",
             "warning"),
        kind("unserved-client", "Client that no node serves",
             "A node calls a service or action that no node of the same system serves, so the "
             "call waits forever, and there is evidence of a mistake, which the message gives: "
             "a remap another launch file gives and this one lacks, a misspelt name, or a "
             "namespace slip. Add the remap or fix the name, or, when the server is outside the "
             "workspace, accept it as an expected external input (X).",
             "note"),
        kind("duplicate-node-name", "Two nodes with one name",
             "Two nodes of a system have the same fully qualified name. ROS 2 starts both, but "
             "parameters, services and tools then reach either one. Nodes that run only because "
             "a launch condition could not be decided may be alternatives and are not counted. "
             "Give one of them another name or namespace.",
             "warning"),
        kind("process-renamed", "A name given to every node of a process",
             "A launch action gives a node name (name=, <node name=...>) to an executable whose "
             "own code builds several nodes. ROS 2 applies the name to every node of the "
             "process, so they all run under one name, and parameters, services and tools reach "
             "any of them. Drop the name and let each node keep its own, or rename one node "
             "with a node-specific rule (--ros-args -r talker:__node:=new_name).",
             "warning"),
        kind("namespace-doubled", "A namespace pushed twice",
             "A launch file pushes a namespace (PushROSNamespace, <push-ros-namespace>, a node's "
             "namespace) onto the same namespace that a file including it pushed already, so its "
             "nodes run in /robot1/robot1 instead of /robot1: ROS 2 nests pushed namespaces. The "
             "usual cause is an including file that both pushes the namespace and passes it down "
             "as the namespace argument. Push it once.",
             "warning"),
        kind("remap-target-unused", "Remap to a name nobody uses",
             "A launch file remaps a port to a name that no other node of the system uses on "
             "the other side, so the remap connects nothing, and a name on the other side is a "
             "misspelling of the target or the same name in another namespace (the message "
             "names it). Fix the target; when the counterpart is outside the workspace, accept "
             "the name as an expected external (X).",
             "warning"),
        kind("remap-unmatched", "Remap that matches no port",
             "A remap rule given to a node renames none of its ports: after ROS 2 expands both "
             "sides, no port of the node has the rule's source name. The rule has no effect; "
             "check its spelling and namespace.",
             "warning"),
        kind("parameter-undeclared", "Parameter nobody declares",
             "A launch file or a parameter file gives a node instance a value for a parameter "
             "that neither its class nor the plugins it loads declare. ROS 2 ignores such a "
             "value without a word, so a misspelt key or a key indented under the wrong node "
             "changes nothing. The message names the nearest declared name. Fix the key, or "
             "remove it. Not judged for nodes that take any parameter or whose declarations the "
             "analysis cannot see whole.",
             "warning"),
        kind("parameter-type", "Parameter value of the wrong type",
             "A node instance is given a value of another type than its class declares the "
             "parameter with (an integer for a double, a quoted \"10\" for an integer). ROS 2 "
             "refuses to set it and the node fails at start-up. Write the value in the declared "
             "type (10.0 for a double).",
             "warning"),
        kind("parameter-range", "Parameter value out of range",
             "A node instance is given a number outside the range the parameter's descriptor "
             "allows; ROS 2 refuses to set it. Give a value inside the range.",
             "warning"),
        kind("parameter-missing", "Parameter without a value",
             "A node class declares a parameter without a default, and neither the launch file "
             "nor its parameter files set it for this instance: reading it fails at run time. "
             "Set it. Not judged when a parameter file of the instance could not be read.",
             "warning"),
        kind("qos-incompatible", "Incompatible QoS",
             "A publisher and a subscription on one topic have QoS policies that ROS 2 will not "
             "match: a best-effort publisher cannot serve a reliable subscription, and a "
             "volatile publisher cannot serve a transient-local one. No message arrives and "
             "ROS 2 only logs an incompatible-QoS event. Reported only when both sides write "
             "their QoS at the call. Make the subscription ask for no more than is offered "
             "(e.g. SensorDataQoS on both sides).",
             "warning"),
        // Reading the workspace
        kind("duplicate-package", "Two packages with one name",
             "Two folders of the workspace declare the same package name. colcon refuses to "
             "build such a workspace, and every lookup by name would pick one copy or the other. "
             "The analysis uses the newer version (the first by path when they agree) and "
             "ignores the other copy; remove one, or put a COLCON_IGNORE file in the copy you "
             "do not build.",
             "error"),
        kind("syntax-error", "Syntax error",
             "Part of a source or launch file could not be parsed. Analysis continues with what "
             "could be read, so ports or nodes in the broken region may be missing.",
             "warning"),
        kind("preprocessor-guess", "Conditional compilation guessed",
             "An #if or #elif condition needs something the workspace does not define: a "
             "function-like macro of an installed header (RCLCPP_VERSION_GTE(28, 0, 0)), "
             "__has_include, or a macro whose value is not a number. Such a condition is taken "
             "as true: its branch is analysed and the #elif / #else branches after it are not. "
             "Ports that exist only in those branches are missing from the diagram.",
             "note"),
        kind("preprocessor-malformed", "Unbalanced conditional compilation",
             "An #endif, #else or #elif without its #if, a second #else, an #if without "
             "#endif, or conditionals nested too deeply to evaluate. The directive is ignored "
             "(an #if without #endif runs to the end of the file); check the file, it does not "
             "build as it is.",
             "warning"),
        kind("parse-failed", "File could not be parsed",
             "The parser gave up on a file (a timeout or an internal limit); nothing in it was "
             "analysed.",
             "error"),
        kind("file-skipped", "File skipped after a crash or an overrun",
             "Analysing this file crashed the analysis worker, ran out of its memory budget or "
             "took longer than its time budget, so the run was repeated without it. Nothing in "
             "it was analysed; everything else was. Please report the file: it found a bug.",
             "error"),
        kind("worker-missing", "Stages run without isolation",
             "The analysis worker rosarch-stages was not found next to the application, so the "
             "stages ran inside it: a crash in analysis would close the window. Reinstall, or "
             "set ROSARCH_STAGES to the worker's path.",
             "warning"),
        kind("stage-failed", "Stage stopped by an internal error",
             "A stage ended with an internal error (an exception) instead of a result, so the "
             "model shown is incomplete: what the stage would have found is missing. The "
             "message names the stage and the error. Run the stage again (F5); if it fails "
             "again, please report it with the message: it is a bug in rosarch, not in the "
             "workspace.",
             "error"),
        kind("file-too-large", "File too large",
             "A file above the size limit was skipped; nothing in it was analysed.", "warning"),
        kind("binary-file", "Binary file", "A file that looks binary was skipped.", "note"),
        kind("unreadable-file", "Unreadable file",
             "A file could not be read (permissions, a broken link); it was skipped.", "warning"),
        kind("unreadable-folder", "Unreadable folder",
             "A folder could not be listed; what it holds was not analysed.", "warning"),
        kind("special-file", "Not a regular file",
             "A file named like a source, launch or package file is a named pipe, a socket, a "
             "device, a dangling symbolic link or a link loop; it was skipped without being "
             "opened.",
             "warning"),
        kind("symlink-loop", "Symbolic link loop or escape",
             "A symbolic link points back into a folder already visited, or out of the "
             "workspace; it was not followed.",
             "note"),
        kind("symlink-outside", "Symbolic link out of the workspace",
             "A symbolic link points outside the workspace; it was not followed, so nothing "
             "outside the workspace is read. Copy what it links to into the workspace to "
             "analyse it.",
             "note"),
        kind("unreadable-name", "File name that is not UTF-8",
             "A file or folder name is not valid UTF-8, so it cannot be opened by name; it "
             "was skipped. Rename it.",
             "warning"),
        kind("not-utf8", "File that is not UTF-8",
             "A file's content is not valid UTF-8; it was read as Latin-1, so non-ASCII "
             "characters in names or comments may be shown wrongly. ROS 2 expects UTF-8.",
             "note"),
        kind("cmake-depth", "CMake nesting too deep",
             "add_subdirectory nesting went beyond the limit; deeper CMakeLists.txt files were "
             "not read, so their executables and plugins are unknown.",
             "warning"),
        kind("no-workspace", "Not a workspace",
             "The folder has no ROS 2 package (no package.xml); nothing was analysed.", "error"),
        kind("helper-depth", "Helper chain too deep",
             "Ports created, and parameters declared, through helpers, behaviours or functions "
             "nested deeper than the analysis follows (or a behaviour tree of more classes than "
             "it follows) are not given to the node. The message names where it stopped.",
             "note"),
        kind("unresolved-entry-point", "Entry point without a node",
             "A setup.py console script names a function whose node class could not be found.",
             "note"),
        kind("executable-without-node", "Executable without a node",
             "A CMake executable's sources contain no node class that analysis could find.",
             "note"),
        // Launch files (stage 2)
        kind("malformed-xml", "Malformed XML launch file",
             "An XML launch file is not well-formed; the actions after the error were not read.",
             "error"),
        kind("malformed-yaml", "Malformed YAML launch file",
             "A YAML launch file could not be parsed; its actions were not read.", "error"),
        kind("missing-attribute", "Launch action without a required attribute",
             "A launch action lacks an attribute ROS 2 requires (a node without pkg or exec, an "
             "include without file); it was skipped.",
             "warning"),
        kind("malformed-substitution", "Malformed substitution",
             "A $(...) substitution could not be read; its value is unknown.", "warning"),
        kind("conflicting-conditions", "Both if and unless",
             "An action has both an if and an unless condition; ROS 2 rejects that.", "warning"),
        kind("invalid-entity", "Unknown launch entity",
             "A YAML launch entry is not a launch action ROS 2 knows; it was skipped.", "warning"),
        kind("nesting-too-deep", "Launch file nesting too deep",
             "A launch file nests deeper than the limit; the deeper part was not read.", "warning"),
        kind("not-a-launch-file", "Not a launch file",
             "A file named like a launch file has no launch description.", "note"),
        kind("no-launch-description", "No generate_launch_description",
             "A Python launch file defines no generate_launch_description function.", "warning"),
        kind("launch-description-unknown", "Launch description not evaluated",
             "The launch description is built in a way the evaluator could not follow; nodes it "
             "starts may be missing.",
             "warning"),
        kind("opaque-function", "OpaqueFunction",
             "An OpaqueFunction runs arbitrary Python at launch time; what it returns was "
             "evaluated only where it could be followed.",
             "note"),
        kind("launch-loop-limit", "Loop limit in a launch file",
             "A loop in a Python launch file ran into the iteration limit; later iterations "
             "were not evaluated.",
             "warning"),
        kind("launch-evaluation-limit", "Evaluation budget exhausted",
             "Evaluating a Python launch file ran out of its step budget; what comes after "
             "that point was not evaluated.",
             "warning"),
        kind("analysis-incomplete", "Analysis incomplete",
             "The analysis worker stopped outside the work on any one file; the stages it "
             "finished are kept and the later ones have no result.",
             "error"),
        kind("check-limit", "Architecture checks cut short",
             "The architecture checks look for a misspelt counterpart of every open port; that "
             "search has a work budget per run so that the checks stay linear. Once it is spent, "
             "the remaining open ports are judged without it, so a misspelling there may go "
             "unreported. Check fewer systems at once (--launch-root) to judge them fully.",
             "note"),
        kind("evaluation-limit", "Value too large",
             "Evaluating a value (a CMake variable, a launch argument or substitution) made it "
             "longer than the size budget, usually by doubling it in a loop; it is left "
             "unresolved. Parameter definition files (generate_parameter_library) past their "
             "depth or size bound are read only up to it.",
             "warning"),
        kind("include-cycle", "Include cycle",
             "A launch file includes itself, directly or through others; the cycle was cut.",
             "error"),
        kind("no-such-launch-file", "Included launch file not found",
             "An include names a file that is not in the workspace; its nodes are missing.",
             "warning"),
        kind("executable-in-other-package", "Executable of another package",
             "A launch file starts an executable under a package that does not build it, and "
             "exactly one other package of the workspace does (it installs the executable "
             "under the first package's name). The instance is typed by that package's class. "
             "Check that this is the executable meant.",
             "note"),
        kind("no-such-parameter-file", "Parameter file not found",
             "A node is given a parameter file that is not in the workspace (or whose path "
             "cannot be decided statically). Its parameters fall back to the launch values and "
             "the defaults in code, so names and guards that depend on them may differ at run "
             "time.",
             "note"),
        kind("parameter-file-unused", "Parameter file without parameters",
             "A parameter file given to a node has no ros__parameters section, so rclcpp reads "
             "nothing from it. Check the file's structure: node name, then ros__parameters.",
             "warning"),
        kind("external-include", "Include from outside the workspace",
             "An include names a launch file of a package outside the workspace; it shows as an "
             "opaque part.",
             "note"),
    };
    return kinds;
}

DiagnosticKind DiagnosticKind::of(const QString &code)
{
    for (const DiagnosticKind &k : all())
        if (k.code == code)
            return k;
    return {code, code,
            QStringLiteral("A finding of kind '%1'; the message says what was seen.").arg(code),
            QStringLiteral("warning")};
}

} // namespace rosarch
