<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>rosarch</name>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="26"/>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="39"/>
        <source>Recover a ROS 2 workspace and report the diagnostics and architecture checks, for CI.
Exit codes: 0 nothing new at or above --fail-on, 1 new findings at or above it, 2 usage error, 3 a file could not be read or written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="45"/>
        <source>The workspace folder to analyse.</source>
        <translation type="unfinished">Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="48"/>
        <source>text (default), json, sarif or junit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="52"/>
        <location filename="../app/commands/diffcommand.cpp" line="70"/>
        <source>Write the report to this file instead of stdout.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="55"/>
        <source>Findings whose keys are in this file (a JSON report of an earlier check, or one key per line) are reported but never fail; so are those accepted in the project.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="60"/>
        <source>Also write every current finding&apos;s key to this file, as a JSON report.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="64"/>
        <source>The lowest severity of a new finding that fails: error (default), warning, info, or never.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="83"/>
        <source>--format must be text, json, sarif or junit, not &apos;%1&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="85"/>
        <source>--fail-on must be error, warning, info or never, not &apos;%1&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="87"/>
        <source>See rosarch check --help.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="96"/>
        <source>Cannot read the baseline %1: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="101"/>
        <source>The baseline %1 cannot be used: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="146"/>
        <source>Cannot write the report to the standard output.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/checkcommand.cpp" line="156"/>
        <source>%1 findings; %2 in the baseline; %3 fail the check (--fail-on %4).
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="50"/>
        <source>Show what changed between two recoveries: node classes and ports, and per launch file its parts, topics, services, actions and connections.
Each side is a folder `rosarch recover` wrote, or a workspace to recover; --rev A --rev B compares two git revisions of one workspace.
Exit codes: 0 no change, 1 changes, 2 usage, 3 an input could not be read.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="59"/>
        <source>Artifact folder or workspace (or, with --rev, the workspace).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="60"/>
        <source>Artifact folder or workspace.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="63"/>
        <source>A git revision of the workspace; give it twice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="66"/>
        <source>text (default) or json.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="81"/>
        <source>--format must be text or json, not &apos;%1&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="83"/>
        <source>--rev takes one workspace and exactly two revisions: rosarch diff &lt;ws&gt; --rev A --rev B.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="86"/>
        <source>diff needs two folders (artifact folders or workspaces), or one workspace and --rev A --rev B.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="90"/>
        <source>Not a folder: %1</source>
        <translation type="unfinished">Kein Ordner: %1
 {1?}</translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="92"/>
        <source>See rosarch diff --help.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="107"/>
        <source>Cannot create a temporary folder.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/diffcommand.cpp" line="125"/>
        <source>Cannot write %1: %2
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="24"/>
        <source>Usage: rosarch site &lt;workspace&gt; --out &lt;dir&gt; [--title &lt;text&gt;] [--source-url &lt;pattern&gt;] [--commit &lt;id&gt;] [--no-decisions | --project &lt;file&gt;] [--in-process] [--no-cache]
</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::AboutDialog</name>
    <message>
        <location filename="../app/aboutdialog.cpp" line="16"/>
        <source>About rosarch</source>
        <translation>Über rosarch</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="28"/>
        <source>Recovers the architecture of a ROS 2 workspace from its source code, build files and launch files, without building or running it.</source>
        <translation>Rekonstruiert die Architektur eines ROS-2-Workspaces aus Quellcode, Build-Dateien und Launch-Files, ohne ihn zu bauen oder auszuführen.</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="31"/>
        <source>Built with</source>
        <translation>Erstellt mit</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="50"/>
        <source>rosarch</source>
        <translation>rosarch</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="51"/>
        <source>Qt</source>
        <translation>Qt</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="52"/>
        <source>%1 (built with %2)</source>
        <translation>%1 (erstellt mit %2)</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="54"/>
        <source>tree-sitter language ABI</source>
        <translation>tree-sitter-Sprach-ABI</translation>
    </message>
    <message>
        <location filename="../app/aboutdialog.cpp" line="55"/>
        <source>QScintilla</source>
        <translation>QScintilla</translation>
    </message>
</context>
<context>
    <name>rosarch::ArchitectureDiffView</name>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="51"/>
        <source>Change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="51"/>
        <source>Element</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="51"/>
        <source>What</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="66"/>
        <source>Compare the recovered architecture with an earlier recovery (an artifact folder or a workspace) or a git revision: File › Compare Architecture.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="114"/>
        <source>Added: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="116"/>
        <source>Removed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="117"/>
        <source>Before: %1
After: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="118"/>
        <source>Select the row to show the %1 in the other views</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="123"/>
        <source>No architecture changes from %1 to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/architecturediffview.cpp" line="124"/>
        <source>%1 changes from %2 to %3: %4 added, %5 removed, %6 changed, %7 renamed.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::AtomicNodeModel</name>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="559"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="561"/>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="563"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodel.cpp" line="565"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="54"/>
        <source>(outside any package)</source>
        <translation>(keinem Paket zugeordnet)</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="59"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="59"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="109"/>
        <source>procedural node</source>
        <translation>prozeduraler Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="111"/>
        <source>plugin: %1</source>
        <translation type="unfinished">Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="117"/>
        <source>%1 (suggested)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodemodeldata.cpp" line="224"/>
        <source>Parameters</source>
        <translation type="unfinished">Parameter</translation>
    </message>
</context>
<context>
    <name>rosarch::AtomicNodePanel</name>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="16"/>
        <source>Filter by name or type (Ctrl+F)</source>
        <translation>Nach Name oder Typ filtern (Ctrl+F)</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="17"/>
        <source>Shows the packages, nodes and ports whose name or type contains this text. Esc clears the filter.</source>
        <translation>Zeigt die Pakete, Knoten und Ports, deren Name oder Typ diesen Text enthält. Esc setzt den Filter zurück.</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="23"/>
        <source>Edit &amp;Description</source>
        <translation>&amp;Beschreibung bearbeiten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="26"/>
        <source>Describe the node&apos;s responsibility (undoable)</source>
        <translation>Die Aufgabe des Knotens beschreiben (kann rückgängig gemacht werden)</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="56"/>
        <source>No node classes analysed yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="128"/>
        <source>How the node reaches this port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="134"/>
        <source>%1. Handed over at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodepanel.cpp" line="139"/>
        <source>%1. Created in %2 at %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::AtomicNodeText</name>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="24"/>
        <source>Publisher</source>
        <translation>Publisher</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="26"/>
        <source>Subscriber</source>
        <translation>Subscriber</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="28"/>
        <source>Service server</source>
        <translation>Service-Server</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="30"/>
        <source>Service client</source>
        <translation>Service-Client</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="32"/>
        <source>Action server</source>
        <translation>Action-Server</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="34"/>
        <source>Action client</source>
        <translation>Action-Client</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="43"/>
        <source>node: %1</source>
        <translation>Knoten: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="45"/>
        <source>plugin: %1</source>
        <translation>Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="45"/>
        <source>exec: %1</source>
        <translation>exec: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="47"/>
        <location filename="../widgets/atomicnodetext.cpp" line="123"/>
        <source>Python</source>
        <translation>Python</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="47"/>
        <location filename="../widgets/atomicnodetext.cpp" line="123"/>
        <source>C++</source>
        <translation>C++</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="49"/>
        <source>lifecycle</source>
        <translation>Lifecycle</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="57"/>
        <source>callback: %1</source>
        <translation>Callback: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="62"/>
        <source>member</source>
        <translation>Member</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="65"/>
        <source>local</source>
        <translation>lokal</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="68"/>
        <source>param: %1</source>
        <translation>Param: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="71"/>
        <source>unresolved: %1</source>
        <translation>unaufgelöst: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="75"/>
        <location filename="../widgets/atomicnodetext.cpp" line="241"/>
        <source>guard: %1</source>
        <translation>Bedingung: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="77"/>
        <source>via: %1</source>
        <translation>über: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="79"/>
        <location filename="../widgets/atomicnodetext.cpp" line="243"/>
        <source>inherited</source>
        <translation>geerbt</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="85"/>
        <source>&lt;b&gt;ROS 2 package&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;ROS-2-Paket&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="88"/>
        <source>Named by node sources only; no package.xml found.</source>
        <translation>Nur durch Knoten-Quelldateien benannt; keine package.xml gefunden.</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="90"/>
        <source>Build type: %1</source>
        <translation>Build-Typ: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="92"/>
        <source>1 atomic node</source>
        <translation>1 atomarer Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="92"/>
        <source>%1 atomic nodes</source>
        <translation>%1 atomare Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="94"/>
        <source>Declared in %1</source>
        <translation>Deklariert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="101"/>
        <source>pluginlib plugin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="102"/>
        <source>Lifecycle node class</source>
        <translation>Lifecycle-Knotenklasse</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="103"/>
        <source>Procedurally built node</source>
        <translation>Prozedural aufgebauter Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="104"/>
        <source>Atomic ROS node class</source>
        <translation>Atomare ROS-Knotenklasse</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="110"/>
        <source>Node name in code: %1</source>
        <translation>Knotenname im Code: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="112"/>
        <source>Derives from: %1</source>
        <translation>Abgeleitet von: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="114"/>
        <source>Exported as a %1 plugin: a node that loads it (by its parameters) gets these ports; {plugin} in a name is the name it is loaded under</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="119"/>
        <source>Started by executable: %1</source>
        <translation>Gestartet durch Executable: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="121"/>
        <source>Component plugin: %1</source>
        <translation>Komponenten-Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="122"/>
        <source>Compile type: %1</source>
        <translation>Kompilierungsart: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="124"/>
        <source>1 port</source>
        <translation>1 Port</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="124"/>
        <source>%1 ports</source>
        <translation>%1 Ports</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="127"/>
        <source>1 declared parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="128"/>
        <source>%1 declared parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="131"/>
        <source>No description (a person removed it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="132"/>
        <location filename="../widgets/atomicnodetext.cpp" line="267"/>
        <source>No description in the code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="134"/>
        <source>Description (%1): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="143"/>
        <source>action %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="144"/>
        <source>service %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="148"/>
        <source>%1 (serves %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/atomicnodetext.cpp" line="152"/>
        <source>%n more</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="153"/>
        <source>Loads, where it is launched: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/atomicnodetext.cpp" line="207"/>
        <source>%n declared</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="209"/>
        <source>takes any parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="215"/>
        <source>&lt;b&gt;Parameters&lt;/b&gt; %1 declares: name, type, default, and the read-only flag and range its descriptor sets. An instance&apos;s values in effect show in the launch tree and the Parameters panel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="221"/>
        <source>It takes any parameter (allow_undeclared_parameters or automatically_declare_parameters_from_overrides): no value given to it is undeclared.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="231"/>
        <source>default: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="233"/>
        <source>no default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="235"/>
        <source>read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="237"/>
        <source>any type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="239"/>
        <source>range: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="250"/>
        <source>&lt;b&gt;Parameter&lt;/b&gt; %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="252"/>
        <source>Declared by %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="254"/>
        <source>Name as written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="256"/>
        <source>{plugin} is the name the plugin is loaded under</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="257"/>
        <source>Type: not fixed by the declaration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="258"/>
        <source>Type: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="260"/>
        <source>Its descriptor allows a value of any type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="261"/>
        <source>Default: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="262"/>
        <source>No default: an instance must be given a value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="264"/>
        <source>Read-only: set at start, never changed while the node runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="266"/>
        <source>Range: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="268"/>
        <source>Description: %1</source>
        <translation>Beschreibung: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="270"/>
        <source>Declared only if: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="272"/>
        <source>Declared through: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="274"/>
        <source>Declared by a base class or helper code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="276"/>
        <source>Declared at %1</source>
        <translation type="unfinished">Deklariert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="156"/>
        <source>Defined at %1</source>
        <translation>Definiert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="166"/>
        <source>Of node %1</source>
        <translation>Gehört zu Knoten %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="168"/>
        <source>Interface type: %1</source>
        <translation>Interface-Typ: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="170"/>
        <source>Callback: %1</source>
        <translation>Callback: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="173"/>
        <source>Name written as a literal</source>
        <translation>Name als Literal angegeben</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="176"/>
        <source>Name taken from a member variable</source>
        <translation>Name aus einer Membervariable übernommen</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="179"/>
        <source>Name taken from a local variable</source>
        <translation>Name aus einer lokalen Variable übernommen</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="182"/>
        <source>Name is the default of parameter &apos;%1&apos;</source>
        <translation>Name ist der Standardwert des Parameters „%1“</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="185"/>
        <source>Name could not be resolved statically: %1</source>
        <translation>Name konnte nicht statisch aufgelöst werden: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="189"/>
        <source>Exists only if: %1</source>
        <translation>Existiert nur, wenn: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="191"/>
        <source>Created through: %1</source>
        <translation>Erzeugt über: %1</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="196"/>
        <source>Reached from the node through %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="199"/>
        <source>Declared in a base class</source>
        <translation>In einer Basisklasse deklariert</translation>
    </message>
    <message>
        <location filename="../widgets/atomicnodetext.cpp" line="201"/>
        <source>Created at %1</source>
        <translation>Erzeugt in %1</translation>
    </message>
</context>
<context>
    <name>rosarch::ChangeSelector</name>
    <message>
        <location filename="../app/changeselector.cpp" line="62"/>
        <source>The %1 %2 was removed: it is not in the model shown.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/changeselector.cpp" line="64"/>
        <source>The %1 %2 is not in the model shown.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CommandLine</name>
    <message>
        <location filename="../app/commands/commandline.cpp" line="37"/>
        <source>Usage:
  rosarch [workspace]                       open the GUI (on the example workspace by default)
  rosarch recover &lt;workspace&gt; --out &lt;dir&gt; [--launch-arg name:=value]... [--launch-root &lt;file&gt;]
                  [--no-decisions | --project &lt;file&gt;] [--render svg|png [--plantuml-jar &lt;file&gt;]]
                  [--in-process] [--no-cache]
                                            run the stages headless and write the artifacts, with
                                            the project applied (default: the workspace&apos;s
                                            rosarch.project.json, when there is one)
  rosarch project check &lt;project file&gt; &lt;workspace&gt; [--in-process]
                                            list the decisions and corrections that no longer
                                            match anything (exit 0 none, 1 orphaned, 2 usage,
                                            3 the project cannot be read)
  rosarch check &lt;workspace&gt; [--format text|json|sarif|junit] [--output &lt;file&gt;]
                [--baseline &lt;file&gt;] [--write-baseline &lt;file&gt;] [--fail-on error|warning|info|never]
                                            report diagnostics and architecture checks for CI
                                            (exit 0 pass, 1 new findings, 2 usage, 3 file error)
  rosarch diff &lt;before&gt; &lt;after&gt; | &lt;workspace&gt; --rev A --rev B [--format text|json]
                                            what changed between two recoveries (artifact
                                            folders, workspaces or git revisions)
  rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
                                            score recovered PlantUML diagrams against a reference
  rosarch suggest &lt;workspace&gt; --out &lt;dir&gt; [--llm-endpoint URL] [--llm-model NAME] [--llm-timeout S]
                                            write checked suggestions to suggestions.json
                                            (deterministic only without an endpoint)
  rosarch export nodl &lt;workspace&gt; --out &lt;dir&gt; [--no-decisions | --project &lt;file&gt;]
                                            write each node class&apos;s parameters, topics, services and
                                            actions as a NoDL document
                                            (&lt;dir&gt;/&lt;package&gt;/&lt;executable&gt;.nodl.json)
  rosarch site &lt;workspace&gt; --out &lt;dir&gt; [--title &lt;text&gt;] [--source-url &lt;pattern&gt;]
                                            write the architecture as a static HTML site (systems,
                                            diagrams, nodes, topics, launch files, findings, search)
  rosarch --help | --version

Artifacts written by recover: atomic_nodes.json, launch_dependencies.json, architecture.json,
diagnostics.json, acd/&lt;ClassName&gt;.puml, ccd/&lt;launch file stem&gt;.puml,
mermaid/&lt;launch file stem&gt;.md, graph/&lt;root launch file stem&gt;.dot (and .svg/.png next to each .puml with --render)
recover and check run the stages in the analysis worker (rosarch-stages), which skips
a file that crashes it or overruns its budget; --in-process runs them in the command.
Per-file results are kept in the analysis cache (the user&apos;s cache folder, rosarch/analysis);
--no-cache (or ROSARCH_NO_CACHE=1) analyses every file again.
Exit codes: 0 ok, 1 analysis finished with errors reported, 2 usage error.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="107"/>
        <source>Recover the architecture of a ROS 2 workspace and write the artifacts.</source>
        <translation>Die Architektur eines ROS-2-Workspaces rekonstruieren und die Artefakte schreiben.</translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="114"/>
        <location filename="../app/commands/exportcommand.cpp" line="41"/>
        <source>The workspace folder to analyse.</source>
        <translation>Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="117"/>
        <source>Folder for the artifacts.</source>
        <translation>Ordner für die Artefakte.</translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="121"/>
        <source>Print only errors.</source>
        <translation>Nur Fehler ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="124"/>
        <source>Also render every ACD and CCD with PlantUML, as svg or png (needs Java and a PlantUML jar).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="130"/>
        <source>The PlantUML jar for --render (default $ROSARCH_PLANTUML_JAR, or one installed with rosarch).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="144"/>
        <source>recover needs --out &lt;dir&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="148"/>
        <source>--render takes svg or png, not &apos;%1&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="178"/>
        <source>Nothing was written; earlier artifacts are unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="217"/>
        <source>Rendering with PlantUML failed:
%1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="227"/>
        <source>Rendered %1 diagrams as %2 with PlantUML.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="232"/>
        <source>Applied %1 accepted decisions and corrections of %2 (--no-decisions writes the model as recovered).
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="349"/>
        <source>Not a folder: %1
rosarch opens a workspace folder; see rosarch --help.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="355"/>
        <source>Unknown command: %1
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="357"/>
        <source>Did you mean: rosarch %1?
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="19"/>
        <source>Usage: rosarch project check &lt;project file&gt; &lt;workspace&gt; [--in-process]
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="30"/>
        <source>correction %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="32"/>
        <source>decision (%1) on %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="34"/>
        <source>%1: warning: orphaned %2: %3; it said: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="44"/>
        <source>List the decisions and corrections of a project that no longer match the workspace.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="52"/>
        <source>The project file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="55"/>
        <source>The workspace folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="58"/>
        <source>Run the stages in this process instead of the analysis worker.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="66"/>
        <source>project takes one subcommand, check, with a project file and a workspace.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="75"/>
        <source>Not a folder: %1
</source>
        <translation>Kein Ordner: %1
</translation>
    </message>
    <message>
        <location filename="../app/commands/projectcommand.cpp" line="96"/>
        <source>%1 decisions and %2 corrections; %3 orphaned.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/commandline.cpp" line="238"/>
        <source>Recovered %1 node classes with %2 ports in %3 packages; %4 launch files, %5 launch-file instances, %6 node instances, %7 unresolved items, %8 composites; in %9 ms; %10 diagnostics (%11 errors).
Wrote %12 files to %13
</source>
        <translation>%1 Knotenklassen mit %2 Ports in %3 Paketen rekonstruiert; %4 Launch-Files, %5 Launch-File-Instanzen, %6 Knoteninstanzen, %7 unaufgelöste Elemente, %8 Komposite; in %9 ms; %10 Diagnosen (%11 Fehler).
%12 Dateien nach %13 geschrieben
</translation>
    </message>
    <message>
        <location filename="../app/commands/workspacerun.cpp" line="27"/>
        <source>%1 needs one workspace folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/workspacerun.cpp" line="33"/>
        <source>Not a folder: %1</source>
        <translation type="unfinished">Kein Ordner: %1
 {1?}</translation>
    </message>
    <message>
        <location filename="../app/commands/workspacerun.cpp" line="45"/>
        <source>--launch-arg expects name:=value, got &apos;%1&apos;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/workspacerun.cpp" line="53"/>
        <source>--no-decisions and --project exclude each other.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/workspacerun.cpp" line="61"/>
        <source>No such file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/workspacerun.cpp" line="88"/>
        <source>The project cannot be used: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="20"/>
        <source>Usage: rosarch export nodl &lt;workspace&gt; --out &lt;dir&gt; [--quiet] [--no-decisions | --project &lt;file&gt;] [--in-process] [--no-cache]
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="33"/>
        <source>Write the recovered node classes of a ROS 2 workspace as NoDL documents (Node Definition Language v2), one per class: &lt;dir&gt;/&lt;package&gt;/&lt;executable&gt;.nodl.json.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="44"/>
        <source>Folder for the documents.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="48"/>
        <source>Do not list what NoDL cannot express.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="67"/>
        <source>export needs a format: nodl.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="69"/>
        <source>Unknown export format &apos;%1&apos;; rosarch exports nodl.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="80"/>
        <source>export needs --out &lt;dir&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/exportcommand.cpp" line="101"/>
        <source>Wrote %1 NoDL documents to %2 (%3 notes on what NoDL cannot express).
</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CompareController</name>
    <message>
        <location filename="../app/comparecontroller.cpp" line="23"/>
        <source>Compare Architecture with &amp;Folder…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="25"/>
        <source>Show what changed against an earlier recovery: a folder rosarch exported or `rosarch recover` wrote, or another workspace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="28"/>
        <source>Compare Architecture with &amp;Git Revision…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="30"/>
        <source>Show what changed against the open workspace at a git revision (a branch, a tag, HEAD~1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="34"/>
        <source>The comparison failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="42"/>
        <source>Compare with an Artifact Folder or a Workspace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="53"/>
        <source>Compare with Git Revision</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="54"/>
        <source>Revision of %1 to compare the current model with (a branch, a tag, a commit, HEAD~1):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="82"/>
        <source>revision %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="103"/>
        <source>Open a workspace and run the stages first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="110"/>
        <source>Comparing with %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="123"/>
        <source>The comparison with %1 was canceled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="125"/>
        <source>Cannot compare with %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="126"/>
        <source>Comparing with %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/comparecontroller.cpp" line="129"/>
        <source>the current model</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CorrectionController</name>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="83"/>
        <source>&amp;Group Selected Parts into Subsystem…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="95"/>
        <source>Remove %1 corrections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="146"/>
        <source>%1: %2 (Ctrl+Z undoes it)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="314"/>
        <source>Plugin class</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="314"/>
        <source>Node class</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="326"/>
        <source>Port (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="338"/>
        <source>Node instance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="338"/>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="344"/>
        <source>%1 %2 [%3]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="353"/>
        <source>Executable (nodes built in code)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="354"/>
        <source>Launch file</source>
        <translation type="unfinished">Launch-File</translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="360"/>
        <source>Topic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="361"/>
        <source>Service</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="362"/>
        <source>Action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="371"/>
        <source>(being worked out…)</source>
        <translation>(wird ermittelt…)</translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="383"/>
        <source>removed by %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="385"/>
        <source>corrected by %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="387"/>
        <source>suggested (an accepted suggestion)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="389"/>
        <source>corrected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="391"/>
        <source>recovered by analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="416"/>
        <source>Restore (Revert %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="420"/>
        <location filename="../app/correctioncontroller.cpp" line="529"/>
        <source>Ctrl+R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="421"/>
        <source>Unmark Reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="421"/>
        <source>Mark Re&amp;viewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="424"/>
        <source>Add &amp;Port…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="425"/>
        <source>Re&amp;move Class…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="431"/>
        <source>Set &amp;Name…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="431"/>
        <location filename="../app/correctioncontroller.cpp" line="441"/>
        <location filename="../app/correctioncontroller.cpp" line="449"/>
        <source>Re&amp;name…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="433"/>
        <source>Set &amp;Type…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="435"/>
        <source>Set &amp;Type… (unknown)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="436"/>
        <source>Re&amp;move Port…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="442"/>
        <source>Re&amp;move…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="443"/>
        <source>Add &amp;Connection…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="446"/>
        <source>Add &amp;Part…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="453"/>
        <source>Remove &amp;Connection…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontroller.cpp" line="468"/>
        <source>Correct</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="49"/>
        <source>Rename</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="60"/>
        <source>Set Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="61"/>
        <source>Analysis left the name of this %1 as an expression: %2. Give the name it has at run time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="66"/>
        <source>Rename the %1 %2 of this class (every instance uses the new name).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="73"/>
        <source>Rename the node instance %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="83"/>
        <source>Rename %1 everywhere it is used.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="93"/>
        <source>Also name the 1 other port of this class written %1 so</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="94"/>
        <source>Also name the %1 other ports of this class written %2 so</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="106"/>
        <source>Set Name of %1 ports</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="113"/>
        <source>Named %1 ports written %2 as “%3” (Ctrl+Z undoes them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="146"/>
        <source>Set Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="148"/>
        <source>Override the interface type of the %1 %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="150"/>
        <source>Analysis could not decide the interface type of the %1 %2 (%3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="152"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="177"/>
        <source>Remove the class %1 from the model (analysis got it wrong).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="180"/>
        <source>Remove the port %1 from its class.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="183"/>
        <source>Remove the node instance %1 (it is not started).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="191"/>
        <source>Remove the connection of %1 through its %2 %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="199"/>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="212"/>
        <source>Add Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="212"/>
        <source>Add a port analysis missed to the class %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="214"/>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="241"/>
        <source>Add Part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="242"/>
        <source>Add a node instance that %1 does not declare (started elsewhere).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="244"/>
        <source>&amp;Class:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="245"/>
        <source>Node &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="263"/>
        <source>Add Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="264"/>
        <source>Connect the node instance %1 to a topic, service or action analysis missed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="267"/>
        <source>&amp;On (absolute name):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="295"/>
        <source>Unmark %1 reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="321"/>
        <source>Group into Subsystem</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="322"/>
        <source>Draw %1 as one subsystem.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="324"/>
        <source>Subsystem &amp;name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="384"/>
        <source>Nothing in this model can take %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="388"/>
        <source>Re-target Correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="389"/>
        <source>%1 (%2) names %3, which matches nothing now. Point it at:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="392"/>
        <source>&amp;Element:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/correctioncontrolleredits.cpp" line="399"/>
        <source>Re-target %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CorrectionDialog</name>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="20"/>
        <source>Publisher</source>
        <translation type="unfinished">Publisher</translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="22"/>
        <source>Subscriber</source>
        <translation type="unfinished">Subscriber</translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="24"/>
        <source>Service server</source>
        <translation type="unfinished">Service-Server</translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="26"/>
        <source>Service client</source>
        <translation type="unfinished">Service-Client</translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="28"/>
        <source>Action server</source>
        <translation type="unfinished">Action-Server</translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="30"/>
        <source>Action client</source>
        <translation type="unfinished">Action-Client</translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="50"/>
        <source>&amp;Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="57"/>
        <source>&amp;Kind:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="63"/>
        <source>package/msg/Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="66"/>
        <source>&amp;Type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="76"/>
        <source>&amp;Element:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="81"/>
        <source>as the launch file&apos;s other nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="82"/>
        <source>Name&amp;space:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="84"/>
        <source>optional: why (kept in the project)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctiondialog.cpp" line="85"/>
        <source>&amp;Reason:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CorrectionIndex</name>
    <message>
        <location filename="../widgets/correctionindex.cpp" line="77"/>
        <source>%1 by %2 (%3): %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionindex.cpp" line="79"/>
        <source>Reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionindex.cpp" line="80"/>
        <source>Corrected</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CorrectionModel</name>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="65"/>
        <source>Rename</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="67"/>
        <source>Set name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="69"/>
        <source>Set type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="71"/>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="73"/>
        <source>Add port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="75"/>
        <source>Add part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="77"/>
        <source>Add connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="79"/>
        <source>Group</source>
        <translation type="unfinished">Gruppe</translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="81"/>
        <source>Review</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="83"/>
        <source>Describe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="130"/>
        <source>applied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="130"/>
        <source>orphaned: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="136"/>
        <source>%1 matches nothing in this model and changes nothing: %2. Re-target it to another element, or remove it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="168"/>
        <source>Correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="170"/>
        <source>Target</source>
        <translation type="unfinished">Ziel</translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="172"/>
        <source>Old → new</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="174"/>
        <source>Reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="176"/>
        <source>Author</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="178"/>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionmodel.cpp" line="180"/>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::CorrectionPanel</name>
    <message>
        <location filename="../widgets/correctionpanel.cpp" line="16"/>
        <source>&amp;Remove Correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionpanel.cpp" line="17"/>
        <source>Re-&amp;target…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionpanel.cpp" line="21"/>
        <source>Revert what the selected corrections changed (undoable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionpanel.cpp" line="23"/>
        <source>Point an orphaned correction at another element of the same kind (undoable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/correctionpanel.cpp" line="56"/>
        <source>No corrections yet. Right-click an element in the node list, the launch tree or the diagram to rename, retype, remove, add or review it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagnosticDetail</name>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="27"/>
        <source>Select a finding to see what it means and how to fix it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="65"/>
        <source>package %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="68"/>
        <source>At %1</source>
        <translation type="unfinished">In %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="70"/>
        <source>Related places</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="80"/>
        <source>Seen in 1 system (root launch file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="81"/>
        <source>Seen in %1 systems (root launch files)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="87"/>
        <source>What this means</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="89"/>
        <source>someone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="92"/>
        <source>Accepted by %1 on %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="93"/>
        <source>Hidden by %1 on %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="95"/>
        <source>Reason: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticdetail.cpp" line="99"/>
        <source>Key: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagnosticFilterBar</name>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="22"/>
        <source>Hidden</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="22"/>
        <source>Accepted</source>
        <translation type="unfinished">Angenommen</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="46"/>
        <source>Show or hide findings of this severity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="51"/>
        <source>Show only findings of one kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="54"/>
        <source>Show only findings in one package</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="57"/>
        <source>Search findings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="60"/>
        <source>Show findings whose message, file, kind or package contains this</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="61"/>
        <source>Also show findings you hid (drawn grey)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="62"/>
        <source>Also show findings you accepted (drawn grey)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="63"/>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="64"/>
        <source>Kind</source>
        <translation type="unfinished">Art</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="65"/>
        <source>Package</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="66"/>
        <source>Group the findings by kind or by package</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="76"/>
        <source>Group by:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="165"/>
        <source>Errors %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="167"/>
        <source>Warnings %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="170"/>
        <source>Info %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="187"/>
        <source>(no package)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="196"/>
        <source>All kinds</source>
        <translation type="unfinished">Alle Arten</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticfilterbar.cpp" line="197"/>
        <source>All packages</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagnosticModel</name>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="269"/>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="271"/>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="273"/>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="289"/>
        <source>(no package)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="295"/>
        <source>%1 (1 finding)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="296"/>
        <source>%1 (%2 findings)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="330"/>
        <source>%1 (accepted)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="331"/>
        <source>%1 (hidden)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="383"/>
        <source>At %1</source>
        <translation>In %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="385"/>
        <source>Seen in %1 systems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="387"/>
        <source>someone</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="389"/>
        <source>Accepted by %1</source>
        <translation>Akzeptiert von %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="389"/>
        <source>Hidden by %1</source>
        <translation>Ausgeblendet von %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="406"/>
        <source>The number of systems (root launch files) the finding was seen in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="411"/>
        <source>Severity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="413"/>
        <source>Kind</source>
        <translation type="unfinished">Art</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="415"/>
        <source>Package</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="417"/>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="419"/>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <location filename="../widgets/diagnosticmodel.cpp" line="421"/>
        <source>Systems</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramController</name>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="39"/>
        <source>Export Diagram as &amp;SVG…</source>
        <translation>Diagramm als &amp;SVG exportieren…</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="40"/>
        <source>Write the composed diagram shown as an SVG drawing</source>
        <translation>Das angezeigte Kompositionsdiagramm als SVG-Zeichnung speichern</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="43"/>
        <source>Export Diagram as &amp;PNG…</source>
        <translation>Diagramm als &amp;PNG exportieren…</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="44"/>
        <source>Write the composed diagram shown as a PNG image</source>
        <translation>Das angezeigte Kompositionsdiagramm als PNG-Bild speichern</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="47"/>
        <source>&amp;Compare with Reference Model…</source>
        <translation>Mit &amp;Referenzmodell vergleichen…</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="48"/>
        <source>Score the recovered model against hand-written PlantUML diagrams and mark the differences in the composed diagram</source>
        <translation>Das rekonstruierte Modell gegen handgeschriebene PlantUML-Diagramme bewerten und die Unterschiede im Kompositionsdiagramm markieren</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="51"/>
        <source>C&amp;lear Comparison</source>
        <translation>&amp;Vergleich aufheben</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="86"/>
        <source>Composed diagram: %1</source>
        <translation>Kompositionsdiagramm: %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="163"/>
        <source>What the talkers were listed for changed with the model. Click a topic, service or action in the composed diagram, or a port in the node list, to see who talks on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="172"/>
        <source>Click a topic, service or action in the composed diagram, or a port in the node list, to see who talks on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="234"/>
        <location filename="../app/diagramcontroller.cpp" line="242"/>
        <location filename="../app/diagramcontroller.cpp" line="259"/>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="278"/>
        <source>port %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="281"/>
        <source>No launch file starts %1, so its port %2 talks on nothing in the composed architecture.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="304"/>
        <source>%1 leaves %2 through its boundary: the launch files that include %2 may have more talkers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="343"/>
        <source>the reference has no diagram for %1</source>
        <translation>die Referenz enthält kein Diagramm für %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="372"/>
        <source>No ACD or CCD diagram could be read in %1.</source>
        <translation>In %1 konnte kein ACD- oder CCD-Diagramm gelesen werden.</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="384"/>
        <source>Compared with %1 (%2): micro F1 %3, macro F1 %4</source>
        <translation>Verglichen mit %1 (%2): Mikro-F1 %3, Makro-F1 %4</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="402"/>
        <source>Reference Model (folder of PlantUML diagrams)</source>
        <translation>Referenzmodell (Ordner mit PlantUML-Diagrammen)</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="408"/>
        <source>Comparison failed: %1</source>
        <translation>Vergleich fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="414"/>
        <source>Comparison with %1</source>
        <translation>Vergleich mit %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="433"/>
        <source>Exported the composed diagram to %1</source>
        <translation>Kompositionsdiagramm nach %1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="434"/>
        <source>Could not write the composed diagram to %1</source>
        <translation>Das Kompositionsdiagramm konnte nicht nach %1 geschrieben werden</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="435"/>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="435"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="449"/>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG-Zeichnung (*.svg)</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="449"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/diagramcontroller.cpp" line="451"/>
        <source>Export Composed Diagram</source>
        <translation>Kompositionsdiagramm exportieren</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramFocus</name>
    <message>
        <location filename="../app/diagramfocus.cpp" line="13"/>
        <source>&amp;Focus Diagram</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/diagramfocus.cpp" line="18"/>
        <source>Give the composed diagram the whole window; again to bring the other panels back (Ctrl+Shift+D)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramMinimap</name>
    <message>
        <location filename="../widgets/diagram/diagramminimap.cpp" line="19"/>
        <source>The whole diagram: click or drag to move the view</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramPanel</name>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="107"/>
        <source>Find in diagram</source>
        <translation>Im Diagramm suchen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="108"/>
        <source>Highlights the parts, topics, services and namespaces whose name contains this text. Enter goes to the next match.</source>
        <translation>Hebt die Teile, Topics, Services und Namespaces hervor, deren Name diesen Text enthält. Enter springt zum nächsten Treffer.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="124"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="124"/>
        <source>Show ports whose name comes from a parameter</source>
        <translation>Ports anzeigen, deren Name aus einem Parameter stammt</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="125"/>
        <source>Inactive</source>
        <translation>Inaktiv</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="130"/>
        <source>External</source>
        <translation>Extern</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="131"/>
        <source>Show includes of launch files outside the workspace</source>
        <translation>Includes von Launch-Files außerhalb des Workspaces anzeigen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="134"/>
        <source>−</source>
        <translation>−</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="135"/>
        <source>Zoom out (-, Ctrl+wheel)</source>
        <translation>Verkleinern (-, Ctrl+Mausrad)</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="136"/>
        <source>+</source>
        <translation>+</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="137"/>
        <source>Zoom in (+, Ctrl+wheel)</source>
        <translation>Vergrößern (+, Ctrl+Mausrad)</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="138"/>
        <source>Fit</source>
        <translation>Einpassen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="139"/>
        <source>Fit the whole diagram in the view (0); a diagram too big to read whole stops at a legible size, the minimap shows the rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="141"/>
        <source>Overview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="142"/>
        <source>Collapse namespaces to one box each and hide the ports of every part; double-click a box to expand it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="144"/>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="243"/>
        <source>Expand All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="145"/>
        <source>Show every namespace and port of this diagram</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="438"/>
        <source>as included by %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="439"/>
        <source>Names, namespaces and arguments are resolved for this include of %1. The exported CCD of %1 is the file on its own, with its declared defaults.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="443"/>
        <source>as launched</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="444"/>
        <source>The root launch file with the launch arguments of the run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="476"/>
        <source>No match</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="477"/>
        <source>%1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="146"/>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="126"/>
        <source>Show parts and ports whose launch condition or guard is false (hidden at first: a system is read as it runs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="148"/>
        <source>Export Diagram</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="150"/>
        <source>SVG image (*.svg);;PNG image (*.png)</source>
        <translation>SVG-Bild (*.svg);;PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="155"/>
        <source>Save the whole diagram as SVG or PNG</source>
        <translation>Das ganze Diagramm als SVG oder PNG speichern</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="193"/>
        <source>No composed diagram yet. Run stage 3 to compose the launch files.</source>
        <translation>Noch kein Kompositionsdiagramm. Führen Sie Stufe 3 aus, um die Launch-Files zusammenzusetzen.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="112"/>
        <source>This launch file is not part of the architecture.</source>
        <translation>Dieses Launch-File ist nicht Teil der Architektur.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="136"/>
        <source>Building diagram…</source>
        <translation>Diagramm wird aufgebaut…</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="163"/>
        <source>%1 starts no nodes and includes no launch files.</source>
        <translation>%1 startet keine Knoten und bindet keine Launch-Files ein.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="164"/>
        <source>Every element of %1 is hidden by the filters.</source>
        <translation>Alle Elemente von %1 sind durch die Filter ausgeblendet.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="172"/>
        <source>%1 has %2 boxes to draw even as an overview; Graphviz would take minutes to lay out more than %3.</source>
        <translation>%1 hat selbst als Übersicht %2 Kästen; Graphviz bräuchte Minuten, um mehr als %3 anzuordnen.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="174"/>
        <source>%1 has %2 boxes to draw; Graphviz would take minutes to lay out more than %3. The overview draws fewer.</source>
        <translation>%1 hat %2 Kästen; Graphviz bräuchte Minuten, um mehr als %3 anzuordnen. Die Übersicht zeichnet weniger.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="178"/>
        <source>Open one of the launch files it includes from the launch tree, or hide elements with the filters.</source>
        <translation>Öffnen Sie im Launch-Baum eine der Launch-Dateien, die sie einbindet, oder blenden Sie Elemente mit den Filtern aus.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelbuild.cpp" line="193"/>
        <source>Laying out…</source>
        <translation>Layout wird berechnet…</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanel.cpp" line="362"/>
        <source>%1

Collapse namespaces or hide elements to make the diagram smaller, then try again.</source>
        <translation>%1

Klappen Sie Namespaces ein oder blenden Sie Elemente aus, um das Diagramm zu verkleinern, und versuchen Sie es dann erneut.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="200"/>
        <source>Expand Namespace %1</source>
        <translation>Namespace %1 ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="201"/>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="228"/>
        <source>Collapse Namespace %1</source>
        <translation>Namespace %1 einklappen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="210"/>
        <source>Open %1</source>
        <translation>%1 öffnen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="218"/>
        <source>Show Ports of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="219"/>
        <source>Hide Ports of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="237"/>
        <source>Show Each Boundary Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagrampanelcollapse.cpp" line="237"/>
        <source>Collapse Boundary Ports</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramRootPicker</name>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="33"/>
        <source>Root launch file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="34"/>
        <source>The root launch file whose system the diagram shows; type to find one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="48"/>
        <source>%1 — executable, 1 node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="49"/>
        <source>%1 — executable, %2 nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="50"/>
        <source>%1 — 1 include</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="51"/>
        <source>%1 — %2 includes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootpicker.cpp" line="75"/>
        <source>%1
%2 launch files included, %3 nodes started, %4 unresolved</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramRootPrompt</name>
    <message>
        <location filename="../widgets/diagram/diagramrootprompt.cpp" line="17"/>
        <source>&lt;b&gt;Which system do you want to see?&lt;/b&gt;&lt;br&gt;This workspace has several root launch files and none is named like a bringup. Choose one; the header&apos;s list switches later, and the choice is remembered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramrootprompt.cpp" line="38"/>
        <source>%1    %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramScene</name>
    <message>
        <location filename="../widgets/diagram/diagramscene.cpp" line="259"/>
        <source>Composed diagram exported by rosarch</source>
        <translation>Von rosarch exportiertes Kompositionsdiagramm</translation>
    </message>
</context>
<context>
    <name>rosarch::DiagramText</name>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="18"/>
        <source>Publisher</source>
        <translation>Publisher</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="20"/>
        <source>Subscriber</source>
        <translation>Subscriber</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="22"/>
        <source>Service server</source>
        <translation>Service-Server</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="24"/>
        <source>Service client</source>
        <translation>Service-Client</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="26"/>
        <source>Action server</source>
        <translation>Action-Server</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="28"/>
        <source>Action client</source>
        <translation>Action-Client</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="37"/>
        <source>publishes to</source>
        <translation>publiziert auf</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="39"/>
        <source>subscribes to</source>
        <translation>abonniert</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="41"/>
        <source>calls</source>
        <translation>ruft auf</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="43"/>
        <source>serves</source>
        <translation>bedient</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="46"/>
        <source>is delegated to the boundary port</source>
        <translation>wird an den Randport delegiert</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="61"/>
        <source>Included launch file %1 (outside the workspace)</source>
        <translation>Eingebundenes Launch-File %1 (außerhalb des Workspaces)</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="62"/>
        <source>Included launch file %1 — double-click to open</source>
        <translation>Eingebundenes Launch-File %1 – Doppelklick zum Öffnen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="68"/>
        <source>Node %1 : %2</source>
        <translation>Knoten %1 : %2</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="70"/>
        <source>The class was not found; its ports are unknown.</source>
        <translation>Die Klasse wurde nicht gefunden; ihre Ports sind unbekannt.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="65"/>
        <source>The ports of its nodes come from the interface model %1.</source>
        <translation>Die Ports ihrer Knoten stammen aus dem Schnittstellenmodell %1.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="72"/>
        <source>Outside the workspace; its ports come from an interface model.</source>
        <translation>Außerhalb des Arbeitsbereichs; ihre Ports stammen aus einem Schnittstellenmodell.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="107"/>
        <source>From the interface model %1 (code outside the workspace), started at %2</source>
        <translation>Aus dem Schnittstellenmodell %1 (Code außerhalb des Arbeitsbereichs), gestartet in %2</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="74"/>
        <source>Namespace: %1</source>
        <translation>Namespace: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="77"/>
        <source>Inactive: its launch condition is false.</source>
        <translation>Inaktiv: Die Launch-Bedingung ist falsch.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="78"/>
        <source>Started at %1</source>
        <translation>Gestartet in %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="88"/>
        <source>Written as: %1</source>
        <translation>Geschrieben als: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="90"/>
        <source>The name could not be resolved statically; this is a guess.</source>
        <translation>Der Name konnte nicht statisch aufgelöst werden; dies ist eine Annahme.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="93"/>
        <source>Remapped to a name built from a launch value nobody sets; the name is a guess.</source>
        <translation>Umbenannt auf einen Namen aus einem Launch-Wert, den niemand setzt; der Name ist eine Vermutung.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="95"/>
        <source>Its namespace or node name is built from a launch value nobody sets; the name is a guess, wired only to names that rest on a guess too.</source>
        <translation>Sein Namespace oder Knotenname ist aus einem Launch-Wert gebildet, den niemand setzt; der Name ist eine Vermutung und nur mit Namen verbunden, die ebenfalls auf einer Vermutung beruhen.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="99"/>
        <source>The name comes from a parameter.</source>
        <translation>Der Name stammt aus einem Parameter.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="101"/>
        <source>Remapped by the launch file.</source>
        <translation>Vom Launch-File per Remap umbenannt.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="103"/>
        <source>Guard: %1</source>
        <translation>Bedingung: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="104"/>
        <source>Guard (false here): %1</source>
        <translation>Bedingung (hier falsch): %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="111"/>
        <source>Created at %1</source>
        <translation>Erzeugt in %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="126"/>
        <source>Namespace %1 — right-click to collapse or expand</source>
        <translation>Namespace %1 – Rechtsklick zum Ein- oder Ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="129"/>
        <source>Topic %1</source>
        <translation>Topic %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="130"/>
        <source>Service %1</source>
        <translation>Service %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="131"/>
        <source>Action %1</source>
        <translation>Action %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="135"/>
        <source>Boundary port %1: %2 %3</source>
        <translation>Randport %1: %2 %3</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="136"/>
        <source>Promoted: nothing inside this launch file is on the other side.</source>
        <translation>Nach außen geführt: Innerhalb dieses Launch-Files gibt es keine Gegenseite.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="138"/>
        <source>The name rests on a launch value nobody sets; it is a guess.</source>
        <translation>Der Name beruht auf einem Launch-Wert, den niemand setzt; er ist eine Vermutung.</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="149"/>
        <source>%1 (%2) %3 %4 — click to see the code</source>
        <translation>%1 (%2) %3 %4 – Klicken, um den Code zu sehen</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="164"/>
        <source>1 element of the reference is missing: %1</source>
        <translation>1 Element der Referenz fehlt: %1</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="165"/>
        <source>%1 elements of the reference are missing: %2</source>
        <translation>%1 Elemente der Referenz fehlen: %2</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="171"/>
        <source>executable, nodes built in %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="172"/>
        <source>launch file (outside the workspace)</source>
        <translation>Launch-File (außerhalb des Workspaces)</translation>
    </message>
    <message>
        <location filename="../widgets/diagram/diagramtext.cpp" line="173"/>
        <source>launch file %1</source>
        <translation>Launch-File %1</translation>
    </message>
</context>
<context>
    <name>rosarch::Document</name>
    <message>
        <location filename="../document/correctioncommand.cpp" line="14"/>
        <source>Rename to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="16"/>
        <source>Set name %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="18"/>
        <source>Set type %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="20"/>
        <source>Remove %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="22"/>
        <source>Add port %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="24"/>
        <source>Add part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="26"/>
        <source>Add connection to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="29"/>
        <source>Group as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="31"/>
        <source>Mark reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="33"/>
        <source>Edit description</source>
        <translation>Beschreibung bearbeiten</translation>
    </message>
    <message>
        <location filename="../document/correctioncommand.cpp" line="46"/>
        <source>Revert: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/decidesuggestioncommand.cpp" line="13"/>
        <source>Accept suggestion</source>
        <translation>Vorschlag annehmen</translation>
    </message>
    <message>
        <location filename="../document/decidesuggestioncommand.cpp" line="14"/>
        <source>Reject suggestion</source>
        <translation>Vorschlag ablehnen</translation>
    </message>
    <message>
        <location filename="../document/document.cpp" line="269"/>
        <source>Accept %1 suggestions</source>
        <translation>%1 Vorschläge annehmen</translation>
    </message>
    <message>
        <location filename="../document/documentfindings.cpp" line="30"/>
        <source>Accept Findings (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/documentfindings.cpp" line="32"/>
        <source>Hide Findings (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/documentfindings.cpp" line="54"/>
        <source>Restore Findings (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/documentproject.cpp" line="35"/>
        <source>%1
The file was kept as %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/documentproject.cpp" line="127"/>
        <source>autosave: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::EvalCommand</name>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="31"/>
        <source>error: %1
</source>
        <translation>Fehler: %1
</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="34"/>
        <source>note: </source>
        <translation>Hinweis: </translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="36"/>
        <source>warning: </source>
        <translation>Warnung: </translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="48"/>
        <source>Score a recovered PlantUML model against a reference model.</source>
        <translation>Ein rekonstruiertes PlantUML-Modell gegen ein Referenzmodell bewerten.</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="53"/>
        <source>The reference model: a .puml file or a folder of them (searched recursively).</source>
        <translation>Das Referenzmodell: eine .puml-Datei oder ein Ordner mit solchen Dateien (rekursiv durchsucht).</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="58"/>
        <source>The recovered model: a .puml file or a folder of them.</source>
        <translation>Das rekonstruierte Modell: eine .puml-Datei oder ein Ordner mit solchen Dateien.</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="62"/>
        <source>Evaluate only ACDs or only CCDs (default: every level present).</source>
        <translation>Nur ACDs oder nur CCDs bewerten (Standard: jede vorhandene Ebene).</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="65"/>
        <source>Print the result as JSON.</source>
        <translation>Das Ergebnis als JSON ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="71"/>
        <source>Usage: rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
</source>
        <translation>Aufruf: rosarch eval --reference &lt;dir|file&gt; --recovered &lt;dir|file&gt; [--level acd|ccd] [--json]
</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="77"/>
        <source>eval needs --reference and --recovered, and no other arguments.

</source>
        <translation>eval benötigt --reference und --recovered und keine weiteren Argumente.

</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="85"/>
        <source>--level expects acd or ccd, got &apos;%1&apos;.
</source>
        <translation>--level erwartet acd oder ccd, erhalten: „%1“.
</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="95"/>
        <source>eval: %1
</source>
        <translation>eval: %1
</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="111"/>
        <source>Nothing to evaluate: no ACD or CCD found in either input.
</source>
        <translation>Nichts zu bewerten: In keiner der Eingaben wurde ein ACD oder CCD gefunden.
</translation>
    </message>
    <message>
        <location filename="../app/commands/evalcommand.cpp" line="118"/>
        <source>eval: %1 is neither an ACD nor a CCD
</source>
        <translation>eval: %1 ist weder ein ACD noch ein CCD
</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="35"/>
        <source>ACD (AtomicClassifierDiagrams)</source>
        <translation>ACD (AtomicClassifierDiagrams)</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="36"/>
        <source>CCD (ComposedClassifierDiagrams)</source>
        <translation>CCD (ComposedClassifierDiagrams)</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="49"/>
        <source>%1 reference diagrams, %2 recovered: %3 matched, %4 missing, %5 extra
</source>
        <translation>%1 Referenzdiagramme, %2 rekonstruiert: %3 zugeordnet, %4 fehlend, %5 zusätzlich
</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="56"/>
        <source>kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="57"/>
        <source>TP</source>
        <translation>TP</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="58"/>
        <source>FP</source>
        <translation>FP</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="59"/>
        <source>FN</source>
        <translation>FN</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="60"/>
        <source>micro P/R/F1</source>
        <translation>Mikro-P/R/F1</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="61"/>
        <source>macro P/R/F1</source>
        <translation>Makro-P/R/F1</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="67"/>
        <source>all kinds</source>
        <translation>alle Arten</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="69"/>
        <source>Per diagram (P R F1 over all kinds):
</source>
        <translation>Je Diagramm (P R F1 über alle Arten):
</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="74"/>
        <source>   missing: no recovered diagram</source>
        <translation>   fehlt: kein rekonstruiertes Diagramm</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="76"/>
        <source>  extra recovered diagram, not scored: %1 (%2)
</source>
        <translation>  zusätzliches rekonstruiertes Diagramm, nicht bewertet: %1 (%2)
</translation>
    </message>
    <message>
        <location filename="../app/commands/evaluationreport.cpp" line="86"/>
        <source>Differences (FP: recovered but not in the reference; FN: in the reference but not recovered):
</source>
        <translation>Unterschiede (FP: rekonstruiert, aber nicht in der Referenz; FN: in der Referenz, aber nicht rekonstruiert):
</translation>
    </message>
</context>
<context>
    <name>rosarch::ExportController</name>
    <message>
        <location filename="../app/exportcontroller.cpp" line="71"/>
        <source>Export NoDL To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="115"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="103"/>
        <source>Open a workspace first: the site shows its architecture.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="115"/>
        <source>Writing the architecture site…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="133"/>
        <source>The architecture site could not be written:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="83"/>
        <source>The NoDL descriptions could not be written:
%1

Choose a folder you can write to, and export again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="86"/>
        <source>NoDL export to %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../app/exportcontroller.cpp" line="90"/>
        <source>Exported %n NoDL descriptions to %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="94"/>
        <source>NoDL: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="37"/>
        <source>Export Artifacts To</source>
        <translation>Artefakte exportieren nach</translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="51"/>
        <source>Export failed</source>
        <translation>Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="52"/>
        <source>The artifacts could not be written to “%1”:
%2

Choose a folder you can write to, or free some space, and export again.</source>
        <translation>Die Artefakte konnten nicht nach „%1“ geschrieben werden:
%2

Wählen Sie einen Ordner, in den Sie schreiben dürfen, oder geben Sie Speicherplatz frei, und exportieren Sie erneut.</translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="55"/>
        <source>Export to %1 failed: %2</source>
        <translation>Export nach %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="58"/>
        <source>Exported 1 file to %1</source>
        <translation>1 Datei nach %1 exportiert</translation>
    </message>
    <message>
        <location filename="../app/exportcontroller.cpp" line="59"/>
        <source>Exported %1 files to %2</source>
        <translation>%1 Dateien nach %2 exportiert</translation>
    </message>
</context>
<context>
    <name>rosarch::FilteredTreePanel</name>
    <message>
        <location filename="../widgets/filteredtreepanel.cpp" line="88"/>
        <source>Nothing analysed yet.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::InspectorPanel</name>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="28"/>
        <source>Description:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="38"/>
        <source>Select a class, port, node instance, launch file, part or topic to see where it comes from and to correct it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="48"/>
        <source>Kind:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="49"/>
        <source>Name:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="50"/>
        <source>Type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="51"/>
        <source>Key:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="52"/>
        <source>Provenance:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="53"/>
        <source>Review:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="100"/>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="103"/>
        <source>✓ reviewed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/inspectorpanel.cpp" line="103"/>
        <source>not reviewed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchArgumentsDialog</name>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="33"/>
        <source>&amp;Remove</source>
        <translation>&amp;Entfernen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="35"/>
        <source>Launch Arguments</source>
        <translation>Launch-Argumente</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="39"/>
        <source>Stage 2 reads the launch files as &lt;code&gt;ros2 launch&lt;/code&gt; would run them: choose the launch file to start from and give values to its arguments. Empty values use the default.</source>
        <translation>Stufe 2 liest die Launch-Files so, wie &lt;code&gt;ros2 launch&lt;/code&gt; sie ausführen würde: Wählen Sie das Launch-File, bei dem begonnen wird, und geben Sie seinen Argumenten Werte. Leere Werte verwenden den Standardwert.</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="46"/>
        <source>The launch file stage 2 starts from</source>
        <translation>Das Launch-File, bei dem Stufe 2 beginnt</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="52"/>
        <source>&amp;Root launch file:</source>
        <translation>&amp;Wurzel-Launch-File:</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Argument</source>
        <translation>Argument</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Default</source>
        <translation>Standardwert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="55"/>
        <source>Declared in</source>
        <translation>Deklariert in</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="80"/>
        <source>&amp;Add Argument</source>
        <translation>Argument &amp;hinzufügen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="81"/>
        <source>Give a value to an argument the list does not show</source>
        <translation>Einem Argument, das die Liste nicht zeigt, einen Wert geben</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="84"/>
        <source>Remove an argument you added</source>
        <translation>Ein von Ihnen hinzugefügtes Argument entfernen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="86"/>
        <source>Use &amp;Defaults</source>
        <translation>&amp;Standardwerte verwenden</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="87"/>
        <source>Clear every value so that each argument uses its default</source>
        <translation>Alle Werte leeren, sodass jedes Argument seinen Standardwert verwendet</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="96"/>
        <source>Run Stage &amp;2</source>
        <translation>Stufe &amp;2 ausführen</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="123"/>
        <source>All top-level launch files</source>
        <translation>Alle Launch-Files der obersten Ebene</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="216"/>
        <source>The value stage 2 gives %1; leave empty for the default</source>
        <translation>Der Wert, den Stufe 2 für %1 verwendet; leer lassen für den Standardwert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="226"/>
        <source>Not declared by a top-level launch file</source>
        <translation>Von keinem Launch-File der obersten Ebene deklariert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="227"/>
        <source>Not declared by this launch file</source>
        <translation>Nicht von diesem Launch-File deklariert</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="233"/>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="237"/>
        <source>%1 has no default: without a value the analysis continues with a guess.</source>
        <translation>%1 hat keinen Standardwert: Ohne Wert arbeitet die Analyse mit einer Annahme weiter.</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="263"/>
        <source>The arguments %1 declares are listed once stage 2 has run with it as the root: run it, then open this dialog again. Values you add here are used.</source>
        <translation>Die Argumente, die %1 deklariert, werden aufgeführt, sobald Stufe 2 mit dieser Datei als Wurzel gelaufen ist: Führen Sie Stufe 2 aus und öffnen Sie dann diesen Dialog erneut. Hier hinzugefügte Werte werden verwendet.</translation>
    </message>
    <message>
        <location filename="../widgets/launchargumentsdialog.cpp" line="268"/>
        <source>No launch arguments are declared. Add one to give it a value.</source>
        <translation>Es sind keine Launch-Argumente deklariert. Fügen Sie eines hinzu, um ihm einen Wert zu geben.</translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchTreeModel</name>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="119"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="121"/>
        <source>Namespace</source>
        <translation>Namespace</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="123"/>
        <source>Package / executable</source>
        <translation>Paket / Executable</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="125"/>
        <source>Class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="127"/>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="144"/>
        <source>(unresolved include)</source>
        <translation>(unaufgelöstes Include)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="190"/>
        <source>namespace scope</source>
        <translation>Namespace-Bereich</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="218"/>
        <source>(not found)</source>
        <translation>(nicht gefunden)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="218"/>
        <source>(external)</source>
        <translation>(extern)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="285"/>
        <source>Parameters</source>
        <translation type="unfinished">Parameter</translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/launchtreemodeldata.cpp" line="287"/>
        <source>%n in effect</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../widgets/launchtreemodeldata.cpp" line="289"/>
        <source>The parameters this instance runs with, and where each comes from: the launch file, a parameter file, or the default in code.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchTreePanel</name>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="17"/>
        <source>&amp;Go to Class</source>
        <translation>Zur &amp;Klasse wechseln</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="21"/>
        <source>Filter by name, namespace, class or executable</source>
        <translation>Nach Name, Namespace, Klasse oder Executable filtern</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="22"/>
        <source>Shows the launch files, namespaces and node instances whose name, namespace, class or executable contains this text. Esc clears the filter.</source>
        <translation>Zeigt die Launch-Files, Namespaces und Knoteninstanzen, deren Name, Namespace, Klasse oder Executable diesen Text enthält. Esc setzt den Filter zurück.</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="30"/>
        <source>Select the atomic node class this node instance runs</source>
        <translation>Die atomare Knotenklasse auswählen, die diese Knoteninstanz ausführt</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="38"/>
        <source>&amp;Expand All</source>
        <translation>Alle &amp;ausklappen</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="40"/>
        <source>&amp;Collapse All</source>
        <translation>Alle &amp;einklappen</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreepanel.cpp" line="67"/>
        <source>No launch files analysed yet.</source>
        <translation>Noch keine Launch-Files analysiert.</translation>
    </message>
</context>
<context>
    <name>rosarch::LaunchTreeText</name>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="59"/>
        <source>Substitution</source>
        <translation>Substitution</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="61"/>
        <source>Condition</source>
        <translation>Bedingung</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="63"/>
        <source>Include</source>
        <translation>Include</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="65"/>
        <source>Opaque function</source>
        <translation>Opake Funktion</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="67"/>
        <source>Argument</source>
        <translation>Argument</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="69"/>
        <source>Python expression</source>
        <translation>Python-Ausdruck</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="71"/>
        <source>Python expression nested too deeply to evaluate</source>
        <translation>Python-Ausdruck zu tief verschachtelt für die Auswertung</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="72"/>
        <source>Expression</source>
        <translation>Ausdruck</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="96"/>
        <source>child node, created in code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="98"/>
        <location filename="../widgets/launchtreetext.cpp" line="120"/>
        <source>if: %1</source>
        <translation>wenn: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="100"/>
        <source>container of 1 component</source>
        <translation>Container mit 1 Komponente</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="101"/>
        <source>container of %1 components</source>
        <translation>Container mit %1 Komponenten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="103"/>
        <source>lifecycle</source>
        <translation>Lifecycle</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="105"/>
        <source>remap: %1</source>
        <translation>Remap: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="107"/>
        <source>param: %1</source>
        <translation>Param: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="109"/>
        <source>1 unresolved</source>
        <translation>1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="110"/>
        <source>%1 unresolved</source>
        <translation>%1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="118"/>
        <source>external</source>
        <translation>extern</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="124"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="125"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="128"/>
        <source>1 include</source>
        <translation>1 Include</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="129"/>
        <source>%1 includes</source>
        <translation>%1 Includes</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="139"/>
        <source>unresolved (%1)</source>
        <translation>unaufgelöst (%1)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="140"/>
        <source>unresolved (%1) · guess: %2</source>
        <translation>unaufgelöst (%1) · Annahme: %2</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="146"/>
        <source>Composable node</source>
        <translation>Komponierbarer Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="147"/>
        <source>Lifecycle node</source>
        <translation>Lifecycle-Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="148"/>
        <source>Node</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="152"/>
        <source>Namespace and name: guesses, built from a launch value nobody sets; so are the relative and private names of its ports</source>
        <translation>Namespace und Name: Vermutungen, gebildet aus einem Launch-Wert, den niemand setzt; ebenso die relativen und privaten Namen seiner Ports</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="155"/>
        <source>Namespace: a guess, built from a launch value nobody sets; so are the relative and private names of its ports</source>
        <translation>Namespace: eine Vermutung, gebildet aus einem Launch-Wert, den niemand setzt; ebenso die relativen und privaten Namen seiner Ports</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="158"/>
        <source>Name: a guess, built from a launch value nobody sets; so are the private names of its ports</source>
        <translation>Name: eine Vermutung, gebildet aus einem Launch-Wert, den niemand setzt; ebenso die privaten Namen seiner Ports</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="161"/>
        <source>Child node: created in code at %1; it runs in the process of the node that creates it, with that launch line&apos;s remaps and parameter files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="165"/>
        <location filename="../widgets/launchtreetext.cpp" line="245"/>
        <source>Package: %1</source>
        <translation>Paket: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="168"/>
        <source>Plugin: %1</source>
        <translation>Plugin: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="168"/>
        <source>Executable: %1</source>
        <translation>Executable: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="171"/>
        <source>Class: %1</source>
        <translation>Klasse: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="176"/>
        <source>Class: not found in the workspace</source>
        <translation>Klasse: nicht im Workspace gefunden</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="177"/>
        <source>Class: not analysed; package %1 is not in the workspace</source>
        <translation>Klasse: nicht analysiert; Paket %1 liegt nicht im Workspace</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="181"/>
        <source>Loaded into container: %1</source>
        <translation>Geladen in Container: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="189"/>
        <source>Condition: %1 (undecidable: kept, as if true)</source>
        <translation>Bedingung: %1 (nicht entscheidbar: beibehalten, als wäre sie wahr)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="190"/>
        <location filename="../widgets/launchtreetext.cpp" line="248"/>
        <source>Condition: %1 (true)</source>
        <translation>Bedingung: %1 (wahr)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="187"/>
        <source>Condition: %1 (&lt;b&gt;false&lt;/b&gt;: not started)</source>
        <translation>Bedingung: %1 (&lt;b&gt;falsch&lt;/b&gt;: nicht gestartet)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="192"/>
        <source>&lt;b&gt;Inactive:&lt;/b&gt; the launch file that declares it is not included</source>
        <translation>&lt;b&gt;Inaktiv:&lt;/b&gt; Das Launch-File, das ihn deklariert, wird nicht eingebunden</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="202"/>
        <source>Remappings:</source>
        <translation>Remaps:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="208"/>
        <source>file %1</source>
        <translation>Datei %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="210"/>
        <source>Parameters given:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="216"/>
        <source>Loads plugins:</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/launchtreetext.cpp" line="219"/>
        <source>Parameters in effect: %n (listed under the node, each with its source)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="294"/>
        <source>default in code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="300"/>
        <source>launch file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="309"/>
        <source>No launch value or parameter file sets it: the default declared in code, at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="313"/>
        <source>From the parameter file %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="315"/>
        <source>Set by the launch file at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="222"/>
        <location filename="../widgets/launchtreetext.cpp" line="259"/>
        <source>Not resolved statically:</source>
        <translation>Nicht statisch aufgelöst:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="198"/>
        <source>%1 → %2 (a guess: built from a launch value nobody sets)</source>
        <translation>%1 → %2 (eine Vermutung: aus einem Launch-Wert, den niemand setzt)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="224"/>
        <source>Declared at %1</source>
        <translation>Deklariert in %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="233"/>
        <source>Executable building its own nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="234"/>
        <source>Launch file</source>
        <translation>Launch-File</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="235"/>
        <source>External include</source>
        <translation>Externes Include</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="236"/>
        <source>Included launch file</source>
        <translation>Eingebundenes Launch-File</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="240"/>
        <source>File: %1</source>
        <translation>Datei: %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="242"/>
        <source>Package %1 is not in the workspace; its nodes are not analysed.</source>
        <translation>Paket %1 liegt nicht im Workspace; seine Knoten werden nicht analysiert.</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="249"/>
        <source>Condition: %1 (&lt;b&gt;false&lt;/b&gt;: not included)</source>
        <translation>Bedingung: %1 (&lt;b&gt;falsch&lt;/b&gt;: nicht eingebunden)</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="251"/>
        <source>&lt;b&gt;Inactive:&lt;/b&gt; the launch file that includes it is not included</source>
        <translation>&lt;b&gt;Inaktiv:&lt;/b&gt; Das Launch-File, das es einbindet, wird nicht eingebunden</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="256"/>
        <source>Launch arguments:</source>
        <translation>Launch-Argumente:</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="261"/>
        <location filename="../widgets/launchtreetext.cpp" line="286"/>
        <source>At %1</source>
        <translation>In %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="261"/>
        <source>Included at %1</source>
        <translation>Eingebunden in %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="269"/>
        <source>&lt;b&gt;Namespace&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Namespace&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="270"/>
        <source>Pushed in %1</source>
        <translation>Gesetzt in %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="272"/>
        <source>1 instance inside this scope</source>
        <translation>1 Instanz in diesem Bereich</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="273"/>
        <source>%1 instances inside this scope</source>
        <translation>%1 Instanzen in diesem Bereich</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="280"/>
        <source>&lt;b&gt;Not resolved statically:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Nicht statisch aufgelöst:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../widgets/launchtreetext.cpp" line="284"/>
        <source>The analysis continued with: %1</source>
        <translation>Die Analyse wurde fortgesetzt mit: %1</translation>
    </message>
</context>
<context>
    <name>rosarch::LlmSettingsDialog</name>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="17"/>
        <source>Ask a language model for suggestions</source>
        <translation>Ein Sprachmodell nach Vorschlägen fragen</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="23"/>
        <source>LLM Settings</source>
        <translation>LLM-Einstellungen</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="26"/>
        <source>Without a model, rosarch still proposes descriptions and groupings from the code. Any OpenAI-compatible server works: OpenAI, Ollama, llama.cpp server, vLLM.</source>
        <translation>Auch ohne Modell schlägt rosarch Beschreibungen und Gruppierungen aus dem Code vor. Jeder OpenAI-kompatible Server funktioniert: OpenAI, Ollama, llama.cpp-Server, vLLM.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="32"/>
        <source>The server&apos;s base URL; /v1/chat/completions is added</source>
        <translation>Die Basis-URL des Servers; /v1/chat/completions wird angehängt</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="37"/>
        <source>0 keeps replies as repeatable as the server allows</source>
        <translation>Mit 0 sind die Antworten so reproduzierbar, wie der Server es zulässt</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="39"/>
        <location filename="../widgets/llmsettingsdialog.cpp" line="41"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="42"/>
        <source>How long one prompt may take, streaming included</source>
        <translation>Wie lange ein Prompt dauern darf, einschließlich Streaming</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="52"/>
        <source>&amp;Endpoint:</source>
        <translation>&amp;Endpunkt:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="53"/>
        <source>&amp;Model:</source>
        <translation>&amp;Modell:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="54"/>
        <source>&amp;Temperature:</source>
        <translation>&amp;Temperatur:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="55"/>
        <source>&amp;Connect timeout:</source>
        <translation>&amp;Verbindungs-Timeout:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="56"/>
        <source>&amp;Request timeout:</source>
        <translation>&amp;Anfrage-Timeout:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="57"/>
        <source>API key:</source>
        <translation>API-Schlüssel:</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="87"/>
        <source>Set in ROSARCH_LLM_API_KEY (not shown, never stored).</source>
        <translation>In ROSARCH_LLM_API_KEY gesetzt (nicht angezeigt, nie gespeichert).</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="89"/>
        <source>Set in OPENAI_API_KEY (not shown, never stored).</source>
        <translation>In OPENAI_API_KEY gesetzt (nicht angezeigt, nie gespeichert).</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="90"/>
        <source>Not set. Local servers need none; for a hosted API set ROSARCH_LLM_API_KEY or OPENAI_API_KEY in the environment before starting rosarch.</source>
        <translation>Nicht gesetzt. Lokale Server benötigen keinen; setzen Sie für eine gehostete API vor dem Start von rosarch ROSARCH_LLM_API_KEY oder OPENAI_API_KEY in der Umgebung.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="132"/>
        <source>Enter the server&apos;s URL, e.g. http://localhost:11434/v1 for Ollama.</source>
        <translation>Geben Sie die URL des Servers ein, z. B. http://localhost:11434/v1 für Ollama.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="137"/>
        <source>The endpoint must be an http:// or https:// URL.</source>
        <translation>Der Endpunkt muss eine http://- oder https://-URL sein.</translation>
    </message>
    <message>
        <location filename="../widgets/llmsettingsdialog.cpp" line="139"/>
        <source>Enter the model name the server knows, e.g. llama3.1 or gpt-4o-mini.</source>
        <translation>Geben Sie den Modellnamen ein, den der Server kennt, z. B. llama3.1 oder gpt-4o-mini.</translation>
    </message>
</context>
<context>
    <name>rosarch::LogView</name>
    <message>
        <location filename="../widgets/logview.cpp" line="27"/>
        <source>&amp;Hide Finding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="28"/>
        <source>&amp;Accept Finding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="29"/>
        <source>Accept Finding with &amp;Reason…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="30"/>
        <source>Re&amp;store Finding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="31"/>
        <source>Accept as E&amp;xpected External</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="48"/>
        <source>H</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="49"/>
        <source>Hide the selected findings: they leave the list (Hidden shows them)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="50"/>
        <source>A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="51"/>
        <source>Accept the selected findings as they are: they leave the list and rosarch check no longer counts them as new</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="53"/>
        <source>U</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="54"/>
        <source>Show the selected hidden or accepted findings again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="55"/>
        <source>X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="57"/>
        <source>Declare the port of the selected findings as meeting something outside the workspace (a driver, teleoperation, a tool): the project records it and the checks no longer report it in any system</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="97"/>
        <source>Progress and messages of stage runs appear here.</source>
        <translation>Hier erscheinen Fortschritt und Meldungen der Stufenausführungen.</translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="157"/>
        <source>Log</source>
        <translation type="unfinished">Protokoll</translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="160"/>
        <source>Log — %1 findings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="161"/>
        <source>Log — %1 findings, %2 shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="304"/>
        <source>Accept Finding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/logview.cpp" line="305"/>
        <source>Why is this finding fine as it is?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::MainMenus</name>
    <message>
        <location filename="../app/mainmenus.cpp" line="62"/>
        <source>&amp;Open Workspace…</source>
        <translation>Workspace ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="65"/>
        <source>Open a ROS 2 workspace folder and recover its architecture</source>
        <translation>Einen ROS-2-Workspace-Ordner öffnen und seine Architektur rekonstruieren</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="68"/>
        <source>&amp;Export Artifacts…</source>
        <translation>Artefakte &amp;exportieren…</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="69"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="71"/>
        <source>Write the JSON artifacts and the PlantUML diagrams: one per node class (ACD) and one per launch file (CCD)</source>
        <translation>Die JSON-Artefakte und die PlantUML-Diagramme schreiben: eines pro Knotenklasse (ACD) und eines pro Launch-File (CCD)</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="80"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="85"/>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="88"/>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="92"/>
        <source>&amp;Find…</source>
        <translation>&amp;Suchen…</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="107"/>
        <source>&amp;Next Finding</source>
        <translation>&amp;Nächster Befund</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="114"/>
        <source>&amp;Previous Finding</source>
        <translation>&amp;Vorheriger Befund</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="94"/>
        <source>Filter the node tree, or the launch tree when it has the focus, by name</source>
        <translation>Den Knotenbaum – oder den Launch-Baum, wenn er den Fokus hat – nach Name filtern</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="74"/>
        <source>Export &amp;NoDL…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="76"/>
        <source>Write one NoDL description per node class: its parameters, topics, services and actions, as ros-tooling/nodl reads them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="121"/>
        <source>&amp;Run All Stages</source>
        <translation>Alle Stufen aus&amp;führen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="123"/>
        <source>Run all</source>
        <translation>Alle ausführen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="125"/>
        <source>Recover the atomic nodes, the launch tree and the composed architecture of the workspace (F5)</source>
        <translation>Die atomaren Knoten, den Launch-Baum und die zusammengesetzte Architektur des Workspaces rekonstruieren (F5)</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="127"/>
        <source>Stage 1 finds node classes, their ports and executables; stage 2 reads the launch files; stage 3 composes them</source>
        <translation>Stufe 1 findet Knotenklassen, ihre Ports und Executables; Stufe 2 liest die Launch-Files; Stufe 3 setzt sie zusammen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="132"/>
        <source>Run Stage &amp;2: Launch Files</source>
        <translation>Stufe &amp;2 ausführen: Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="134"/>
        <source>Stage 2</source>
        <translation>Stufe 2</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="136"/>
        <source>Read the launch files again against the current atomic nodes, with the chosen launch arguments (F6)</source>
        <translation>Die Launch-Files mit den gewählten Launch-Argumenten erneut lesen und mit den aktuellen atomaren Knoten abgleichen (F6)</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="138"/>
        <source>Re-run stage 2 only: launch files, includes, namespaces and node instances</source>
        <translation>Nur Stufe 2 erneut ausführen: Launch-Files, Includes, Namespaces und Knoteninstanzen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="143"/>
        <source>Launch &amp;Arguments…</source>
        <translation>&amp;Launch-Argumente…</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="145"/>
        <source>Arguments</source>
        <translation>Argumente</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="146"/>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="148"/>
        <source>Choose the root launch file and the launch argument values for stage 2</source>
        <translation>Das Wurzel-Launch-File und die Werte der Launch-Argumente für Stufe 2 wählen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="152"/>
        <source>&amp;Cancel Stage</source>
        <translation>Stufe &amp;abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="154"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="156"/>
        <source>Stop the running stage and keep the previous result (Esc)</source>
        <translation>Die laufende Stufe anhalten und das vorherige Ergebnis behalten (Esc)</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="159"/>
        <source>&amp;Suggest (Stage 4)</source>
        <translation>&amp;Vorschläge (Stufe 4)</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="160"/>
        <source>LLM</source>
        <translation>LLM</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="162"/>
        <source>Propose node descriptions and subsystem groupings for review (F7); asks the LLM when one is configured</source>
        <translation>Knotenbeschreibungen und Subsystem-Gruppierungen zur Prüfung vorschlagen (F7); fragt das LLM, wenn eines konfiguriert ist</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="173"/>
        <source>&amp;Watch Workspace for Changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="176"/>
        <source>Analyse again when a source, build, launch or parameter file of the workspace changes on disk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="183"/>
        <source>&amp;Reset Layout</source>
        <translation>Layout &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="186"/>
        <source>&amp;About rosarch</source>
        <translation>&amp;Über rosarch</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="192"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="199"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="202"/>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="212"/>
        <source>Export Architecture &amp;Site…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="214"/>
        <source>Write the accepted model as a static HTML site a newcomer reads in a browser: systems with their diagrams, nodes, topics, launch files, findings and a search</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="234"/>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="246"/>
        <source>Main</source>
        <translation>Hauptwerkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="265"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="260"/>
        <source>&amp;Toolbar</source>
        <translation>&amp;Werkzeugleiste</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="42"/>
        <source>&amp;Go</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="304"/>
        <source>&amp;Stages</source>
        <translation>&amp;Stufen</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="47"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="319"/>
        <source>No recent workspaces</source>
        <translation>Keine zuletzt geöffneten Workspaces</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="324"/>
        <source>&amp;%1 %2 — %3</source>
        <translation>&amp;%1 %2 — %3</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="332"/>
        <source>&amp;Clear Menu</source>
        <translation>Menü &amp;leeren</translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="278"/>
        <source>&amp;Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="286"/>
        <source>Select an element to correct it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="291"/>
        <source>Show &amp;Corrections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainmenus.cpp" line="294"/>
        <source>Show &amp;Inspector</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::MainWindow</name>
    <message>
        <location filename="../app/mainwindow.cpp" line="304"/>
        <source>Open ROS 2 Workspace</source>
        <translation>ROS-2-Workspace öffnen</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="315"/>
        <source>Cannot open workspace</source>
        <translation>Workspace kann nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="316"/>
        <source>The folder “%1” does not exist or is not a folder.

Choose a ROS 2 workspace (a folder containing packages with a package.xml) with File → Open Workspace, or drop one onto the window.</source>
        <translation>Der Ordner „%1“ existiert nicht oder ist kein Ordner.

Wählen Sie über Datei → Workspace öffnen einen ROS-2-Workspace (einen Ordner mit Paketen, die eine package.xml enthalten) aus, oder ziehen Sie einen Workspace auf das Fenster.</translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="62"/>
        <source>rosarch[*]</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../app/mainwindow.cpp" line="226"/>
        <source>%n file(s) changed on disk (%1); analysing again</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="241"/>
        <source>This workspace has more than %L1 files and folders to watch, so only its folders are watched: files added, removed or replaced (as most editors save) start a new analysis, a file edited in place does not. Press F5 after such an edit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="361"/>
        <source>%1 (new project)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="363"/>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="364"/>
        <source>%1[*] — rosarch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="391"/>
        <source>accepted in the Log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="403"/>
        <source>Declared %1 as expected external; checking again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="403"/>
        <source>, </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/mainwindow.cpp" line="153"/>
        <source>Cannot show %1</source>
        <translation>%1 kann nicht angezeigt werden</translation>
    </message>
</context>
<context>
    <name>rosarch::NavigationController</name>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="66"/>
        <source>&amp;Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="68"/>
        <source>&amp;Forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="72"/>
        <source>Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="73"/>
        <source>Forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="307"/>
        <source>Back to %1 (Alt+Left)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="308"/>
        <source>Back (Alt+Left): nothing visited before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="310"/>
        <source>Forward to %1 (Alt+Right)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="311"/>
        <source>Forward (Alt+Right): nothing to go forward to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="318"/>
        <source>%1 in the node list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="320"/>
        <source>%1 in the launch tree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="322"/>
        <source>%1 in the diagram</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="324"/>
        <source>%1:%2 in the source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/navigationcontroller.cpp" line="326"/>
        <source>the finding “%1”</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::NodeDescription</name>
    <message>
        <location filename="../document/nodedescription.cpp" line="80"/>
        <source>No description in the code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/nodedescription.cpp" line="82"/>
        <source>from the code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/nodedescription.cpp" line="84"/>
        <source>from an accepted suggestion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../document/nodedescription.cpp" line="86"/>
        <source>written by a person</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::PanelDocks</name>
    <message>
        <location filename="../app/paneldocks.cpp" line="45"/>
        <source>Atomic nodes</source>
        <translation>Atomare Knoten</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="46"/>
        <source>Launch tree</source>
        <translation>Launch-Baum</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="47"/>
        <source>Composed diagram</source>
        <translation>Kompositionsdiagramm</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="48"/>
        <source>Source</source>
        <translation>Quelltext</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="49"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="56"/>
        <source>Suggestions</source>
        <translation>Vorschläge</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="58"/>
        <source>Architecture changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="60"/>
        <source>Talkers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="62"/>
        <source>Parameters</source>
        <translation type="unfinished">Parameter</translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="65"/>
        <source>Corrections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/paneldocks.cpp" line="66"/>
        <source>Inspector</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::ParameterController</name>
    <message>
        <location filename="../app/parametercontroller.cpp" line="54"/>
        <source> (takes any parameter)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameterpanel.cpp" line="21"/>
        <source>Filter parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameterpanel.cpp" line="38"/>
        <source>Parameters</source>
        <translation type="unfinished">Parameter</translation>
    </message>
    <message>
        <location filename="../widgets/parameterpanel.cpp" line="54"/>
        <source>Select a node instance in the launch tree, or a node class, to see its parameters.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/parameterpanel.cpp" line="66"/>
        <source>%1: %n parameters declared</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/parameterpanel.cpp" line="67"/>
        <source>%1 declares %n parameters</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../widgets/parameterpanel.cpp" line="69"/>
        <source>, %n given but not declared</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../widgets/parameterpanel.cpp" line="71"/>
        <source>%1 has no parameters the analysis could find.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameterpanel.cpp" line="72"/>
        <source>%1 declares no parameters the analysis could find.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::ParameterTableModel</name>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="41"/>
        <source>%1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="45"/>
        <source>launch file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="47"/>
        <source>default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="48"/>
        <source>not set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="75"/>
        <source>not declared: ROS 2 ignores this value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="85"/>
        <source>Declared by the plugin loaded as %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="87"/>
        <source>Declared at %1:%2</source>
        <translation type="unfinished">Deklariert in %1:%2</translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="89"/>
        <source>Set at %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="91"/>
        <source>Read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="93"/>
        <source>Range: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="117"/>
        <source>Name</source>
        <translation type="unfinished">Name</translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="119"/>
        <source>Type</source>
        <translation type="unfinished">Typ</translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="121"/>
        <source>Default</source>
        <translation type="unfinished">Standardwert</translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="123"/>
        <source>Value</source>
        <translation type="unfinished">Wert</translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="125"/>
        <source>Source</source>
        <translation type="unfinished">Quelltext</translation>
    </message>
    <message>
        <location filename="../widgets/parametertablemodel.cpp" line="127"/>
        <source>Description</source>
        <translation type="unfinished">Beschreibung</translation>
    </message>
</context>
<context>
    <name>rosarch::ProjectController</name>
    <message>
        <location filename="../app/projectcontroller.cpp" line="29"/>
        <source>&amp;New Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="30"/>
        <source>Open &amp;Project…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="31"/>
        <source>&amp;Save Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="32"/>
        <source>Save Project &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="33"/>
        <source>Recent Pro&amp;jects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="36"/>
        <source>rosarch projects (*.project.json);;JSON files (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="42"/>
        <source>Start an empty project (no decisions, no corrections, the default launch options) on the open workspace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="45"/>
        <source>Ctrl+Shift+O</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="46"/>
        <source>Open a rosarch project file and the workspace it belongs to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="52"/>
        <source>Open Project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="57"/>
        <source>Write the launch options, decisions and corrections to the project file (by default rosarch.project.json in the workspace)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="61"/>
        <source>Ctrl+Shift+S</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="62"/>
        <source>Write the project to another file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="74"/>
        <location filename="../app/projectcontroller.cpp" line="223"/>
        <source>The project file could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="75"/>
        <source>Cannot read the project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="76"/>
        <source>%1

rosarch opened the workspace with an empty project. Saving writes a new project file; the unreadable one stays where it was kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="101"/>
        <source>the new project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="104"/>
        <source>Unsaved changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="105"/>
        <source>The project of “%1” has changes that are not saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="110"/>
        <source>Save them to %1, discard them, or cancel and stay with this project?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="136"/>
        <source>Recover unsaved changes?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="137"/>
        <source>rosarch did not close normally while the project of “%1” had unsaved changes. They were kept on %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="143"/>
        <source>&amp;Recover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="147"/>
        <source>Recover them (the project shows as modified until you save it), or discard them and keep the project as saved in %1?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="150"/>
        <source>Recover them (the project shows as modified until you save it), or discard them (the workspace has no saved project yet)?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="152"/>
        <source>Autosave file: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="158"/>
        <source>Discarded the autosaved changes %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="164"/>
        <source>The autosaved changes could not be recovered: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="165"/>
        <source>Cannot recover the changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="166"/>
        <source>%1

The autosave file was left where it is.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="169"/>
        <source>Recovered the unsaved changes from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="170"/>
        <source>Recovered the unsaved changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="194"/>
        <source>Save Project As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="203"/>
        <source>The project could not be saved to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="207"/>
        <source>Saved the project to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="208"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="218"/>
        <location filename="../app/projectcontroller.cpp" line="224"/>
        <location filename="../app/projectcontroller.cpp" line="230"/>
        <source>Cannot open project</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="219"/>
        <source>The project file “%1” does not exist.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="225"/>
        <source>%1

The file was not opened and is left as it is.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="231"/>
        <source>The workspace of the project “%1” is not there: %2.

Move the project file into its workspace, or open the workspace and save the project again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="248"/>
        <source>Opened the project %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="260"/>
        <source>No workspace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="260"/>
        <source>A project belongs to a workspace: open one with File → Open Workspace, then start a new project on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="267"/>
        <source>Started a new project on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="278"/>
        <source>No recent projects</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="283"/>
        <source>&amp;%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="290"/>
        <source>Not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/projectcontroller.cpp" line="296"/>
        <source>&amp;Clear Menu</source>
        <translation type="unfinished">Menü &amp;leeren</translation>
    </message>
</context>
<context>
    <name>rosarch::RenderController</name>
    <message>
        <location filename="../app/rendercontroller.cpp" line="20"/>
        <source>Export and &amp;Render with PlantUML…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="22"/>
        <source>Write the artifacts and render every ACD and CCD to SVG with PlantUML (needs Java and a PlantUML jar)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="25"/>
        <source>PlantUML &amp;Jar…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="26"/>
        <source>Choose the PlantUML jar used for rendering</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="55"/>
        <source>Choose the PlantUML Jar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="57"/>
        <source>Java archives (*.jar)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="61"/>
        <source>PlantUML jar set to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="72"/>
        <source>Export and Render To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="85"/>
        <source>Java not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="86"/>
        <source>Rendering with PlantUML needs a Java runtime. Install one (on Debian: apt install default-jre-headless) or set JAVA_HOME, then render again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="91"/>
        <location filename="../app/rendercontroller.cpp" line="98"/>
        <source>PlantUML jar not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="92"/>
        <source>The PlantUML jar chosen in File › PlantUML Jar… is no longer there:
%1

Choose it again, then render again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="99"/>
        <source>Rendering needs plantuml.jar (from plantuml.com, or scripts/fetch-plantuml.sh in rosarch&apos;s sources). Choose it with File › PlantUML Jar…, or set ROSARCH_PLANTUML_JAR, then render again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="107"/>
        <source>Export failed</source>
        <translation type="unfinished">Export fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="108"/>
        <source>The artifacts could not be written to “%1”:
%2

Choose a folder you can write to, or free some space, and try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="133"/>
        <source>Rendered %1 diagrams to SVG in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="136"/>
        <source>PlantUML failed (exit code %1): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="140"/>
        <source>Rendering failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="146"/>
        <source>Java could not be started: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/rendercontroller.cpp" line="151"/>
        <source>Rendering %1 diagrams with PlantUML…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::SiteCommand</name>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="37"/>
        <source>Write the architecture of a ROS 2 workspace as a static HTML site: an index of its systems, a page per system with its composed diagram, per node class, topic, service, action, launch file and package, the findings, and a search. No server and no network are needed to read it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="44"/>
        <source>The workspace folder to analyse.</source>
        <translation type="unfinished">Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="46"/>
        <source>Folder for the site (empty, new, or a site written before).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="50"/>
        <source>The site&apos;s title (default: the workspace folder&apos;s name).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="54"/>
        <source>Link source lines to hosted source: a pattern with {path} (relative to the repository root), {line} and {commit}, e.g. https://github.com/org/repo/blob/{commit}/{path}#L{line}. Default: relative links to the workspace&apos;s files.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="61"/>
        <source>The commit for {commit} (default: the workspace repository&apos;s HEAD).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="71"/>
        <source>site needs --out &lt;dir&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="75"/>
        <source>--source-url needs {path} in its pattern, e.g. https://github.com/org/repo/blob/{commit}/{path}#L{line}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="95"/>
        <source>--source-url has {commit}, but %1 is not in a git repository: give --commit &lt;id&gt;.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="101"/>
        <source>note: %1 is not in a git repository; {path} is relative to it.
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="114"/>
        <source>%1 holds no ROS 2 package (no package.xml) and no launch file: there is no architecture to write. Give the workspace folder (the one with src/).
</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/sitecommand.cpp" line="129"/>
        <source>Wrote %1 files (%2 KB) to %3 in %4 s (analysis %5 s); open %6.
</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::SiteExport</name>
    <message>
        <location filename="../app/commands/siteexport.cpp" line="40"/>
        <source>The site export was canceled; nothing was written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/commands/siteexport.cpp" line="50"/>
        <source>Wrote the architecture site (%1 files) to %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::SiteExportDialog</name>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="29"/>
        <source>Export Architecture Site</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="38"/>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="39"/>
        <source>Choose the folder for the site</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="55"/>
        <source>Link source lines to hosted source: {path} is the file&apos;s path in the git repository, {line} its line, {commit} the commit. Empty: relative links to the workspace&apos;s files.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="62"/>
        <source>the repository&apos;s HEAD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="63"/>
        <source>A commit, tag or branch for {commit}; needed when the workspace is not in a git repository.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="69"/>
        <source>&amp;Folder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="72"/>
        <source>&amp;Title:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="73"/>
        <source>&amp;Source URL:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="74"/>
        <source>&amp;Commit:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="82"/>
        <source>&amp;Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="87"/>
        <source>Writes the accepted model as a static HTML site: a page per system, node, topic and launch file, the findings and a search. The folder must be empty, new, or a site written before.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="107"/>
        <source>Choose a folder for the site.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="110"/>
        <source>The source URL needs {path} in its pattern, where the file&apos;s path goes, e.g. https://github.com/org/repo/blob/{commit}/{path}#L{line}.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="126"/>
        <source>Export Architecture Site To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/siteexportdialog.cpp" line="151"/>
        <source>The source URL has {commit}, but %1 is not in a git repository: give the commit, tag or branch to link to.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::SourceView</name>
    <message>
        <location filename="../widgets/sourceview.cpp" line="165"/>
        <source>Cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="167"/>
        <source>%1 is too large to show (%2 MB)</source>
        <translation>%1 ist zu groß für die Anzeige (%2 MB)</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="356"/>
        <source>Select a node, port, launch item or diagnostic to see its source.</source>
        <translation>Wählen Sie einen Knoten, einen Port, ein Launch-Element oder eine Diagnose aus, um den Quelltext zu sehen.</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="366"/>
        <source>lines %1–%2</source>
        <translation>Zeilen %1–%2</translation>
    </message>
    <message>
        <location filename="../widgets/sourceview.cpp" line="368"/>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
</context>
<context>
    <name>rosarch::StageController</name>
    <message>
        <location filename="../app/stagecontroller.cpp" line="130"/>
        <source>Reading launch files…</source>
        <translation>Launch-Files werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="126"/>
        <source>Stages 1–3 (atomic nodes, launch files, composition) started on %1</source>
        <translation>Stufen 1–3 (atomare Knoten, Launch-Files, Komposition) für %1 gestartet</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="25"/>
        <source>%1 took %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="33"/>
        <source>Stage 1 (atomic nodes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="35"/>
        <source>Stage 2 (launch files)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="37"/>
        <source>Stage 3 (composition)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="39"/>
        <source>Stage %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="127"/>
        <source>Recovering atomic nodes, launch files and their composition…</source>
        <translation>Atomare Knoten, Launch-Files und ihre Komposition werden rekonstruiert…</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="129"/>
        <source>Stages 2–3 (launch files, composition) started on %1</source>
        <translation>Stufen 2–3 (Launch-Files, Komposition) für %1 gestartet</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="144"/>
        <source>Stages 1–3 finished in %1 s: the result is the same as the one shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="152"/>
        <location filename="../app/stagecontroller.cpp" line="174"/>
        <source>Showing the result in the window took %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="156"/>
        <source>Stages 1–3 finished in %1 s: %2 nodes, %3 ports, %4 launch files, %5 node instances, %6 composites, %7 diagnostics</source>
        <translation>Stufen 1–3 in %1 s abgeschlossen: %2 Knoten, %3 Ports, %4 Launch-Files, %5 Knoteninstanzen, %6 Komposite, %7 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="176"/>
        <source>Stages 2–3 finished in %1 s: %2 launch files, %3 launch-file instances, %4 node instances, %5 composites, %6 diagnostics</source>
        <translation>Stufen 2–3 in %1 s abgeschlossen: %2 Launch-Files, %3 Launch-File-Instanzen, %4 Knoteninstanzen, %5 Komposite, %6 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="194"/>
        <location filename="../app/stagecontroller.cpp" line="204"/>
        <source>Stages 1–3</source>
        <translation>Stufen 1–3</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="194"/>
        <location filename="../app/stagecontroller.cpp" line="204"/>
        <source>Stages 2–3</source>
        <translation>Stufen 2–3</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="195"/>
        <source>%1 canceled; the previous result is kept.</source>
        <translation>%1 abgebrochen; das vorherige Ergebnis bleibt erhalten.</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="196"/>
        <source>%1 canceled</source>
        <translation>%1 abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="206"/>
        <source>%1 stopped without a result; the previous result is kept. %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/stagecontroller.cpp" line="207"/>
        <source>%1 stopped: the analysis worker failed (see the log)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>rosarch::StageRunner</name>
    <message>
        <location filename="../app/stagerunner.cpp" line="16"/>
        <source>Stage %1 stopped with an internal error: %2</source>
        <translation>Stufe %1 wurde wegen eines internen Fehlers abgebrochen: %2</translation>
    </message>
</context>
<context>
    <name>rosarch::StatusPresenter</name>
    <message>
        <location filename="../app/statuspresenter.cpp" line="67"/>
        <source>1 package</source>
        <translation>1 Paket</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="67"/>
        <source>%1 packages</source>
        <translation>%1 Pakete</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="68"/>
        <source>1 node</source>
        <translation>1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="68"/>
        <source>%1 nodes</source>
        <translation>%1 Knoten</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="70"/>
        <source>1 plugin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="70"/>
        <source>%1 plugins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="71"/>
        <source>1 port</source>
        <translation>1 Port</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="71"/>
        <source>%1 ports</source>
        <translation>%1 Ports</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="72"/>
        <source>1 launch file</source>
        <translation>1 Launch-File</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="72"/>
        <source>%1 launch files</source>
        <translation>%1 Launch-Files</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="73"/>
        <source>1 instance</source>
        <translation>1 Instanz</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="73"/>
        <source>%1 instances</source>
        <translation>%1 Instanzen</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="74"/>
        <source>1 unresolved</source>
        <translation>1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="74"/>
        <source>%1 unresolved</source>
        <translation>%1 unaufgelöst</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="75"/>
        <source>1 composite</source>
        <translation>1 Komposit</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="75"/>
        <source>%1 composites</source>
        <translation>%1 Komposite</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="76"/>
        <source>1 diagnostic</source>
        <translation>1 Diagnose</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="76"/>
        <source>%1 diagnostics</source>
        <translation>%1 Diagnosen</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="78"/>
        <source>Stage 1: packages, atomic node classes and their ports.
Stage 2: launch files found, node instances they start and expressions that could not be resolved statically.
Stage 3: composites, one per launch-file instance.</source>
        <translation>Stufe 1: Pakete, atomare Knotenklassen und ihre Ports.
Stufe 2: gefundene Launch-Files, die von ihnen gestarteten Knoteninstanzen und Ausdrücke, die nicht statisch aufgelöst werden konnten.
Stufe 3: Komposite, eines pro Launch-File-Instanz.</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="93"/>
        <source>The run stopped before it had a result, so nothing is known yet.

Run it again with Stages → Run All.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="97"/>
        <source>Open a ROS 2 workspace (File → Open Workspace) to see its node classes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="97"/>
        <source>Open a ROS 2 workspace (File → Open Workspace) to see its launch tree.</source>
        <translation>Öffnen Sie einen ROS-2-Workspace (Datei → Workspace öffnen), um seinen Launch-Baum zu sehen.</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="97"/>
        <source>Open a ROS 2 workspace (File → Open Workspace) to see its composed diagrams.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="102"/>
        <source>Reading the workspace…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="103"/>
        <source>Reading the launch files…</source>
        <translation>Die Launch-Files werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="104"/>
        <source>Composing the launch files…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="108"/>
        <source>No ROS 2 package in this folder.

rosarch finds packages by their package.xml. Open the folder that holds them: a workspace, or its src folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="108"/>
        <source>No ROS 2 package in this folder, so no launch files either.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="108"/>
        <source>No ROS 2 package in this folder: there is nothing to compose.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="114"/>
        <source>No node classes found.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="116"/>
        <source>No launch files found in this workspace.

Stage 2 reads *.launch.py, *.launch.xml and *.launch.yaml files and any file holding a launch description.</source>
        <translation>In diesem Workspace wurden keine Launch-Files gefunden.

Stufe 2 liest *.launch.py-, *.launch.xml- und *.launch.yaml-Dateien sowie jede Datei, die eine Launch-Beschreibung enthält.</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="119"/>
        <source>No launch file was analysed as a root.

Choose one in Stages → Launch Arguments…</source>
        <translation>Es wurde kein Launch-File als Wurzel analysiert.

Wählen Sie eines unter Stufen → Launch-Argumente…</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="123"/>
        <source>No launch files, so nothing to compose: a composed diagram shows what a launch file (or a program that builds several nodes) starts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="125"/>
        <source>No composed diagram yet. Run stage 3 to compose the launch files.</source>
        <translation type="unfinished">Noch kein Kompositionsdiagramm. Führen Sie Stufe 3 aus, um die Launch-Files zusammenzusetzen.</translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="170"/>
        <source>atomic nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="170"/>
        <source>launch files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="170"/>
        <source>composition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="174"/>
        <source>Stage %1: %2 — %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="176"/>
        <source>Stage %1: %2 — %3/%4 composites</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="180"/>
        <source>Stage %1: %2 — %3/%4 files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/statuspresenter.cpp" line="190"/>
        <source>[%1/%2] %3</source>
        <translation>[%1/%2] %3</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestCommand</name>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="22"/>
        <source>Recover a ROS 2 workspace and propose checked suggestions (node descriptions, subsystem groupings, unresolved names).</source>
        <translation>Einen ROS-2-Workspace rekonstruieren und geprüfte Vorschläge machen (Knotenbeschreibungen, Subsystem-Gruppierungen, unaufgelöste Namen).</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="29"/>
        <source>The workspace folder to analyse.</source>
        <translation>Der zu analysierende Workspace-Ordner.</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="32"/>
        <source>Folder for suggestions.json.</source>
        <translation>Ordner für suggestions.json.</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="36"/>
        <source>OpenAI-compatible endpoint (with or without /v1); default $ROSARCH_LLM_ENDPOINT. The API key is read from $ROSARCH_LLM_API_KEY or $OPENAI_API_KEY.</source>
        <translation>OpenAI-kompatibler Endpunkt (mit oder ohne /v1); Standard: $ROSARCH_LLM_ENDPOINT. Der API-Schlüssel wird aus $ROSARCH_LLM_API_KEY oder $OPENAI_API_KEY gelesen.</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="43"/>
        <source>Model name; default $ROSARCH_LLM_MODEL.</source>
        <translation>Modellname; Standard: $ROSARCH_LLM_MODEL.</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="48"/>
        <source>Request timeout in seconds (default 120).</source>
        <translation>Timeout einer Anfrage in Sekunden (Standard: 120).</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="53"/>
        <source>Folder whose prompt files override the built-in ones; default $ROSARCH_PROMPT_DIR.</source>
        <translation>Ordner, dessen Prompt-Dateien die eingebauten ersetzen; Standard: $ROSARCH_PROMPT_DIR.</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="59"/>
        <source>Print only errors.</source>
        <translation>Nur Fehler ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="67"/>
        <source>suggest needs a workspace folder and --out &lt;dir&gt;.
</source>
        <translation>suggest benötigt einen Workspace-Ordner und --out &lt;dir&gt;.
</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="73"/>
        <source>Not a folder: %1
</source>
        <translation>Kein Ordner: %1
</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="88"/>
        <source>--llm-timeout expects a positive number of seconds, got &apos;%1&apos;.
</source>
        <translation>--llm-timeout erwartet eine positive Anzahl Sekunden, erhalten: „%1“.
</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="108"/>
        <source>LLM: %1
</source>
        <translation>LLM: %1
</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="114"/>
        <source>LLM error: %1
</source>
        <translation>LLM-Fehler: %1
</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="122"/>
        <source>Cannot create %1
</source>
        <translation>%1 kann nicht erstellt werden
</translation>
    </message>
    <message>
        <location filename="../app/commands/suggestcommand.cpp" line="140"/>
        <source>%1 suggestions (%2); %3 discarded (%4); %5 prompts, ~%6 tokens (characters / 4).
Wrote %7
</source>
        <translation>%1 Vorschläge (%2); %3 verworfen (%4); %5 Prompts, ~%6 Tokens (Zeichen / 4).
%7 geschrieben
</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionController</name>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="35"/>
        <source>Suggestions: accepted %1 (%2) as one step (Undo takes it back)</source>
        <translation>Vorschläge: %1 (%2) in einem Schritt angenommen (Rückgängig nimmt sie zurück)</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="58"/>
        <source>Suggestions: %1</source>
        <translation>Vorschläge: %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="64"/>
        <source>Suggestions: the decisions could not be saved: %1</source>
        <translation>Vorschläge: Die Entscheidungen konnten nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="91"/>
        <source>Suggestions need a recovered model: open a workspace and run the stages first.</source>
        <translation>Vorschläge benötigen ein rekonstruiertes Modell: Öffnen Sie einen Workspace und führen Sie zuerst die Stufen aus.</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="93"/>
        <source>Nothing to suggest on yet</source>
        <translation>Noch keine Grundlage für Vorschläge</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="100"/>
        <source>Suggestions: the LLM is turned on but has no endpoint; only the deterministic suggestions are made (LLM Settings…).</source>
        <translation>Vorschläge: Das LLM ist eingeschaltet, hat aber keinen Endpunkt; es werden nur die deterministischen Vorschläge gemacht (LLM-Einstellungen…).</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="121"/>
        <source>LLM settings: %1</source>
        <translation>LLM-Einstellungen: %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="122"/>
        <source>LLM settings: the LLM is off; suggestions come from the code only</source>
        <translation>LLM-Einstellungen: Das LLM ist aus; Vorschläge stammen nur aus dem Code</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="129"/>
        <source>LLM off</source>
        <translation>LLM aus</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="133"/>
        <source>LLM: %1 at %2</source>
        <translation>LLM: %1 auf %2</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="139"/>
        <source>Asking the LLM…</source>
        <translation>Das LLM wird gefragt…</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="139"/>
        <source>Reading the code…</source>
        <translation>Der Code wird gelesen…</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="140"/>
        <source>Suggestions started (deterministic, then the LLM)</source>
        <translation>Vorschläge gestartet (deterministisch, danach das LLM)</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="141"/>
        <source>Suggestions started (deterministic; the LLM is off)</source>
        <translation>Vorschläge gestartet (deterministisch; das LLM ist aus)</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="142"/>
        <source>Looking for suggestions…</source>
        <translation>Vorschläge werden gesucht…</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="148"/>
        <source>%1: %L2 characters received</source>
        <translation>%1: %L2 Zeichen empfangen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="163"/>
        <source>1 description</source>
        <translation>1 Beschreibung</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="163"/>
        <source>%1 descriptions</source>
        <translation>%1 Beschreibungen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="165"/>
        <source>1 grouping</source>
        <translation>1 Gruppierung</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="165"/>
        <source>%1 groupings</source>
        <translation>%1 Gruppierungen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="167"/>
        <source>1 name</source>
        <translation>1 Name</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="167"/>
        <source>%1 names</source>
        <translation>%1 Namen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="168"/>
        <source>Suggestions: %1 new</source>
        <translation>Vorschläge: %1 neu</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="172"/>
        <source>, %1 already decided</source>
        <translation>, %1 bereits entschieden</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="177"/>
        <source>, %1 discarded: %2</source>
        <translation>, %1 verworfen: %2</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="191"/>
        <source>Suggestions: the LLM failed: %1 The suggestions from the code are shown; check LLM Settings… and run again.</source>
        <translation>Vorschläge: Das LLM ist fehlgeschlagen: %1 Die Vorschläge aus dem Code werden angezeigt; prüfen Sie die LLM-Einstellungen… und führen Sie den Lauf erneut aus.</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="195"/>
        <source>Done: code and %1</source>
        <translation>Fertig: Code und %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="196"/>
        <source>Done: from the code</source>
        <translation>Fertig: aus dem Code</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="199"/>
        <source>The LLM failed; see the log</source>
        <translation>Das LLM ist fehlgeschlagen; siehe Protokoll</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="200"/>
        <source>Suggestions: the LLM failed (see the log); the suggestions from the code are shown</source>
        <translation>Vorschläge: Das LLM ist fehlgeschlagen (siehe Protokoll); die Vorschläge aus dem Code werden angezeigt</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="211"/>
        <source>Canceled</source>
        <translation>Abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="213"/>
        <source>Suggestions canceled; %1</source>
        <translation>Vorschläge abgebrochen; %1</translation>
    </message>
    <message>
        <location filename="../app/suggestioncontroller.cpp" line="214"/>
        <source>Suggestions canceled</source>
        <translation>Vorschläge abgebrochen</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionModel</name>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="107"/>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="109"/>
        <source>Grouping</source>
        <translation>Gruppierung</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="111"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="120"/>
        <source>Descriptions</source>
        <translation>Beschreibungen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="122"/>
        <source>Groupings</source>
        <translation>Gruppierungen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="124"/>
        <source>Names</source>
        <translation>Namen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="133"/>
        <source>Pending</source>
        <translation>Offen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="135"/>
        <source>Accepted</source>
        <translation>Angenommen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="137"/>
        <source>Rejected</source>
        <translation>Abgelehnt</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="209"/>
        <source>“%1” (quoted from the code)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="233"/>
        <source>deterministic</source>
        <translation>deterministisch</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="274"/>
        <source>%1 · %2</source>
        <translation>%1 · %2</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="303"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="305"/>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="307"/>
        <source>Proposal</source>
        <translation>Vorschlag</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="309"/>
        <source>Origin</source>
        <translation>Herkunft</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionmodel.cpp" line="311"/>
        <source>Evidence</source>
        <translation>Belege</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionPanel</name>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="62"/>
        <source>All statuses</source>
        <translation>Alle Status</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="67"/>
        <source>Show the suggestions of one status</source>
        <translation>Die Vorschläge mit einem bestimmten Status anzeigen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="68"/>
        <source>All kinds</source>
        <translation>Alle Arten</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="73"/>
        <source>Show the suggestions of one kind</source>
        <translation>Die Vorschläge einer bestimmten Art anzeigen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="161"/>
        <source>Select a suggestion to see its rationale and evidence.</source>
        <translation>Wählen Sie einen Vorschlag aus, um Begründung und Belege zu sehen.</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="184"/>
        <source>Run Suggestions</source>
        <translation>Vorschläge ermitteln</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="185"/>
        <source>Propose node descriptions and subsystem groupings from the code (and ask the LLM when one is configured)</source>
        <translation>Knotenbeschreibungen und Subsystem-Gruppierungen aus dem Code vorschlagen (und das LLM fragen, wenn eines konfiguriert ist)</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="188"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="189"/>
        <source>Stop asking the LLM; what arrived so far is kept</source>
        <translation>Das LLM nicht weiter fragen; bereits Empfangenes bleibt erhalten</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="191"/>
        <source>LLM Settings…</source>
        <translation>LLM-Einstellungen…</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="192"/>
        <source>Endpoint, model and timeouts of the language model</source>
        <translation>Endpunkt, Modell und Timeouts des Sprachmodells</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="195"/>
        <source>Accept</source>
        <translation>Annehmen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="196"/>
        <source>Apply the proposed change (Enter); undo with Ctrl+Z</source>
        <translation>Die vorgeschlagene Änderung übernehmen (Enter); rückgängig mit Ctrl+Z</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="198"/>
        <source>Reject</source>
        <translation>Ablehnen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="199"/>
        <source>Dismiss the proposal; it is not asked again (Delete)</source>
        <translation>Den Vorschlag verwerfen; er wird nicht erneut gestellt (Entf)</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="201"/>
        <location filename="../widgets/suggestionpanel.cpp" line="426"/>
        <source>Accept All</source>
        <translation>Alle annehmen</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="202"/>
        <source>Accept every pending suggestion of this kind, as one step on the undo stack</source>
        <translation>Alle offenen Vorschläge dieser Art annehmen, als ein Schritt im Rückgängig-Verlauf</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="398"/>
        <source>No suggestions</source>
        <translation>Keine Vorschläge</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="401"/>
        <source>%1 pending · %2 accepted · %3 rejected</source>
        <translation>%1 offen · %2 angenommen · %3 abgelehnt</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="425"/>
        <source>Accept All %1 (%2)</source>
        <translation>Alle %1 annehmen (%2)</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="440"/>
        <source>Looking for suggestions…</source>
        <translation>Vorschläge werden gesucht…</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="443"/>
        <source>No suggestions yet.

Run Suggestions proposes node descriptions from docstrings and comments and subsystem groupings from the topic graph; with an LLM configured it also asks the model.</source>
        <translation>Noch keine Vorschläge.

„Vorschläge ermitteln“ schlägt Knotenbeschreibungen aus Docstrings und Kommentaren sowie Subsystem-Gruppierungen aus dem Topic-Graphen vor; ist ein LLM konfiguriert, wird zusätzlich das Modell gefragt.</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="447"/>
        <source>No suggestion matches the filter.</source>
        <translation>Kein Vorschlag entspricht dem Filter.</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="465"/>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="470"/>
        <source>Proposal, quoted from the code (the repository&apos;s words, not rosarch&apos;s):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="473"/>
        <source>Proposal:</source>
        <translation>Vorschlag:</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="477"/>
        <source>Evidence:</source>
        <translation>Belege:</translation>
    </message>
    <message>
        <location filename="../widgets/suggestionpanel.cpp" line="492"/>
        <source>Origin:</source>
        <translation>Herkunft:</translation>
    </message>
</context>
<context>
    <name>rosarch::SuggestionRunner</name>
    <message>
        <location filename="../app/suggestionrunner.cpp" line="15"/>
        <source>The suggestion run stopped with an internal error: %1</source>
        <translation>Der Vorschlagslauf wurde wegen eines internen Fehlers abgebrochen: %1</translation>
    </message>
</context>
<context>
    <name>rosarch::TalkersPanel</name>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="21"/>
        <source>publisher</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="23"/>
        <source>subscriber</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="25"/>
        <source>service server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="27"/>
        <source>service client</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="29"/>
        <source>action server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="33"/>
        <source>action client</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="57"/>
        <source>1 publisher</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="58"/>
        <source>%1 publishers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="59"/>
        <source>1 server</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="60"/>
        <source>%1 servers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="61"/>
        <source>1 subscriber</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="62"/>
        <source>%1 subscribers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="63"/>
        <source>1 client</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="64"/>
        <source>%1 clients</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="66"/>
        <source>%1, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="67"/>
        <source>%1, %2, %3 inactive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="73"/>
        <source>topic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="75"/>
        <source>service</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="76"/>
        <source>action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="82"/>
        <source>%1 of %2 (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="84"/>
        <source>Port %1, written “%2”%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="86"/>
        <source>, remapped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="90"/>
        <source>The name is a guess: the analysis could not decide it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="92"/>
        <source>Inactive: its launch condition or guard is false.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="94"/>
        <source>Created at %1:%2</source>
        <translation type="unfinished">Erzeugt in %1:%2</translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="108"/>
        <source>Node</source>
        <translation type="unfinished">Knoten</translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="108"/>
        <source>Role</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="108"/>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="108"/>
        <source>Class</source>
        <translation type="unfinished">Klasse</translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="123"/>
        <source>Click a topic, service or action in the composed diagram, or a port in the node list, to see who talks on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="147"/>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="148"/>
        <source>%1 · %2</source>
        <translation type="unfinished">%1 · %2</translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="149"/>
        <source>%1 · %2 · %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="176"/>
        <source>%1  %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="193"/>
        <source>, </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="195"/>
        <source>%1 ports</source>
        <translation type="unfinished">%1 Ports</translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="206"/>
        <source>%1 talks on nothing in %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="208"/>
        <source>No node in %2 talks on %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="210"/>
        <source>Talkers on %1 in %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/talkerspanel.cpp" line="211"/>
        <source>%1
%2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
