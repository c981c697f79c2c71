//! Round 23 of unseen projects (issue #13): what real programs and their users need, run end to
//! end through `ladderc run`:
//! - a computed array index out of range names its first site at the end of the run: the access
//!   as written, its POU, file and line, the index and the bounds it missed (`runtime: array index
//!   out of range (first: temps[i] in Main at plant.st:9, index 11 outside 1..10; the first
//!   element used)`; before: "array index out of range" alone, however large the project); the
//!   pointer, NULL and memory-function sites name their line too;
//! - the 50 diagnostics shown per file keep room for the file's errors first (before: 50 warnings
//!   could hide every error of a rejected file), and W1411 (an input written inside its POU) is
//!   one per input (before: one per write);
//! - DT, DATE and TOD convert to and from numbers and bit strings (`DT_TO_UDINT`, `UDINT_TO_DT`,
//!   `TOD_TO_DWORD`: seconds since 1970 for DT and DATE, milliseconds for TOD, as CODESYS,
//!   TwinCAT and OSCAT; before: E1019);
//! - `c : FB_Count();` in a METHOD's VAR passes nothing, as in a program's (before: E0329);
//! - an unknown function is one E1019 per POU (before: one per call, 104 in one project);
//! - a TwinCAT solution's NC links of another PLC project's instance are not applied to the one
//!   compiled (before: a false E1057);
//! - a nested comment before a `.TcPOU`'s block keyword (before: E0321).
//! - a project's FUNCTION_BLOCK named as a standard block (`TON`) is W1446 at its name (before:
//!   silent, the standard timer replaced).
//! - B&R's system libraries' `.fun` declarations (`operator.fun`'s ADD, `standard.fun`'s TON) are
//!   not compiled (W0021): the standard blocks stay (before: empty blocks replaced them, and a whole
//!   project overflowed the stack in the ANY-input rewrite, which now never rewrites its own hidden
//!   inputs).
//! - `MEMCPY` of a pointer expression over an undeclared name: E1001 names it, and the project's
//!   other checks run (before: one E1035 that stopped them all); `p + n` of a POINTER TO variable.

mod common;
use common::{check_text, column, in_dir, run_text, write_in};

/// `FOR i := 1 TO 11` over `ARRAY[1..10]`, the classic off-by-one: the run goes on (element 1 read
/// and written instead, as the memory model says), and the report names the access, the POU, the
/// file and line, the index and the bounds. The first site is the one named, not a later one.
#[test]
fn an_index_out_of_range_names_its_first_site() {
    let src = "PROGRAM Main
VAR
  temps : ARRAY[1..10] OF INT;
  grid : ARRAY[0..2, 0..3] OF INT;
  i, j, sum : INT;
END_VAR
sum := 0;
FOR i := 1 TO 11 DO
  temps[i] := i;
  sum := sum + temps[i];
END_FOR
j := 7;
grid[1, j] := 5;
END_PROGRAM
";
    let (trace, stderr) = run_text("plant.st", src, 2, "Main.sum,Main.temps[1]");
    assert!(
        stderr.contains(
            "runtime: array index out of range (first: temps[i] in Main at plant.st:9, index 11 \
             outside 1..10; the first element used)"
        ),
        "{stderr}"
    );
    // the run went on: element 1 took the 11th write (11), and sum read it back after
    let sum = column(&trace, "Main.sum");
    assert_eq!(sum[0], 55.0 + 11.0, "{trace}");
    assert_eq!(column(&trace, "Main.temps[1]")[0], 11.0, "{trace}");
}

/// A multi-dimensional index and a located (`%MW`) array each name their site (file and line of
/// the access), and a pointer moved outside its variable names its line too.
#[test]
fn other_index_and_pointer_sites_name_their_line() {
    let src = "PROGRAM Main
VAR
  grid : ARRAY[0..2, 0..3] OF INT;
  j : INT := 7;
END_VAR
grid[1, j] := 5;
END_PROGRAM
";
    let (_, stderr) = run_text("grid.st", src, 1, "Main.j");
    assert!(
        stderr.contains(
            "array index out of range (first: grid[1, j] in Main at grid.st:6, index 7 outside 0..3;"
        ),
        "{stderr}"
    );

    let src = "PROGRAM Main
VAR
  words AT %MW10 : ARRAY[1..4] OF WORD;
  k : INT := 9;
  buf : ARRAY[0..3] OF DINT;
  p : POINTER TO DINT;
  v : DINT;
END_VAR
words[k] := 16#BEEF;
p := ADR(buf);
v := p[k];
END_PROGRAM
";
    let (_, stderr) = run_text("mem.st", src, 1, "Main.v");
    assert!(
        stderr.contains(
            "array index out of range (first: words[k] in Main at mem.st:9, index 9 outside 1..4;"
        ),
        "{stderr}"
    );
    assert!(
        stderr.contains(
            "runtime: pointer outside its variable dereferenced (first: p[k] in Main at mem.st:11; \
             zero read, write dropped)"
        ),
        "{stderr}"
    );
}

/// A file whose 51 warnings (W1411, 51 inputs each written) come before its one error: the error is shown (errors take the room of
/// the 50 shown per file first), in the human and the short format, and the note counts the
/// warnings left out (before: 50 warnings shown, "2 more diagnostics not shown", exit 1 with no
/// error on the screen; sphere-usecases' OpenPLC simulator hid its 8 E2002 so).
#[test]
fn the_per_file_limit_never_hides_an_error_behind_warnings() {
    let mut src = String::from("FUNCTION_BLOCK FB_W\nVAR_INPUT\n");
    for k in 0..51 {
        src.push_str(&format!("x{k} : INT;\n"));
    }
    src.push_str("END_VAR\n");
    for k in 0..51 {
        src.push_str(&format!("x{k} := {k};\n"));
    }
    src.push_str("END_FUNCTION_BLOCK\nPROGRAM Main\nVAR w : FB_W; END_VAR\nw(x0 := 1);\ny := 2;\nEND_PROGRAM\n");
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("cap.st");
    std::fs::write(&f, &src).unwrap();
    for format in ["human", "short"] {
        let out = common::ladderc()
            .args(["--message-format", format, "check"])
            .arg(&f)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{stderr}");
        assert!(stderr.contains("E1001"), "{format}: {stderr}");
        assert_eq!(stderr.matches("W1411").count(), 49, "{format}: {stderr}");
        assert!(
            stderr.contains("note: 2 more diagnostics in"),
            "{format}: {stderr}"
        );
    }
}

/// W1411 is given once per input, at its first write (before: once per write, 18 times for one
/// input of a real OpenPLC program, which filled the screen); the program still runs with the
/// POU's own copy written, as CODESYS and matiec do.
#[test]
fn an_input_written_inside_its_block_is_one_warning() {
    let src = "FUNCTION_BLOCK FB_Clamp
VAR_INPUT x : INT; END_VAR
VAR_OUTPUT y : INT; END_VAR
IF x > 10 THEN x := 10; END_IF
IF x < 0 THEN x := 0; END_IF
x := x * 2;
y := x;
END_FUNCTION_BLOCK
PROGRAM Main
VAR c : FB_Clamp; out : INT; END_VAR
c(x := 42);
out := c.y;
END_PROGRAM
";
    let (code, lines) = check_text("clamp.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    let w: Vec<_> = lines.iter().filter(|l| l.contains("W1411")).collect();
    assert_eq!(w.len(), 1, "{lines:?}");
    assert!(w[0].starts_with("clamp.st:4:"), "{lines:?}");
    let (trace, _) = run_text("clamp.st", src, 1, "Main.out");
    assert_eq!(column(&trace, "Main.out"), [20.0]);
}

/// DT, DATE and TOD convert to and from integers, bit strings and reals (`DT_TO_UDINT`,
/// `UDINT_TO_DT`, `TOD_TO_DWORD`, ...), counted as CODESYS, TwinCAT and OSCAT count them: DT and
/// DATE in seconds since 1970-01-01, TOD in milliseconds since midnight (OSCAT's `HOUR` is
/// `TOD_TO_DWORD(t) / 3600000`). Before: E1019 "unknown function" at each (an Elna/Beremiz
/// project's `DT_TO_UDINT`, 69 calls in oscatBasic).
#[test]
fn dates_and_times_of_day_convert_with_numbers() {
    let src = "PROGRAM Main
VAR
  t0 : DT := DT#1970-01-02-00:00:10;
  d0 : DATE := D#1970-01-03;
  tod0 : TOD := TOD#01:00:00.5;
  s, ds, ms : UDINT;
  w, hour : DWORD;
  r : LREAL;
  back_dt, back_date, back_tod, back_real : BOOL;
END_VAR
s := DT_TO_UDINT(t0);
ds := DATE_TO_UDINT(d0);
ms := TOD_TO_UDINT(tod0);
w := DT_TO_DWORD(t0);
hour := TOD_TO_DWORD(tod0) / 3600000;
r := DT_TO_LREAL(t0);
back_dt := UDINT_TO_DT(s + 50) = DT#1970-01-02-00:01:00;
back_date := DWORD_TO_DATE(DWORD#432000) = D#1970-01-06;
back_tod := UDINT_TO_TOD(ms + 500) = TOD#01:00:01;
back_real := LREAL_TO_DT(r + 0.5) = DT#1970-01-02-00:00:10.5;
END_PROGRAM
";
    let watch = "Main.s,Main.ds,Main.ms,Main.w,Main.hour,Main.r,Main.back_dt,Main.back_date,Main.back_tod,Main.back_real";
    let (trace, stderr) = run_text("dates.st", src, 1, watch);
    assert!(!stderr.contains("error"), "{stderr}");
    let v = |n: &str| column(&trace, n)[0];
    assert_eq!(v("Main.s"), 86410.0, "{trace}");
    assert_eq!(v("Main.ds"), 172800.0, "{trace}");
    assert_eq!(v("Main.ms"), 3600500.0, "{trace}");
    assert_eq!(v("Main.w"), 86410.0, "{trace}");
    assert_eq!(v("Main.hour"), 1.0, "{trace}");
    assert_eq!(v("Main.r"), 86410.0, "{trace}");
    for flag in ["back_dt", "back_date", "back_tod", "back_real"] {
        assert_eq!(v(&format!("Main.{flag}")), 1.0, "{flag}: {trace}");
    }
}

/// `c : FB_Count();` in a METHOD's VAR, as in a program's: the empty FB_init list of a block
/// without FB_init passes nothing (TwinCAT compiles OpenCommissioning's test methods so; before:
/// E0329 in the method, accepted in the program since round 22). The method's instance starts
/// anew at each call (counts 2 each time), the program's counts on.
#[test]
fn an_empty_fb_init_list_in_a_method_passes_nothing() {
    let src = "FUNCTION_BLOCK FB_Count
VAR_INPUT inc : INT := 1; END_VAR
VAR_OUTPUT n : INT; END_VAR
n := n + inc;
END_FUNCTION_BLOCK
FUNCTION_BLOCK FB_User
VAR_OUTPUT total : INT; END_VAR
METHOD Tally : INT
VAR c : FB_Count(); END_VAR
c();
c();
Tally := c.n;
END_METHOD
total := THIS^.Tally();
END_FUNCTION_BLOCK
PROGRAM Main
VAR top : FB_Count(); u : FB_User; r, n : INT; END_VAR
top();
u();
r := u.total;
n := top.n;
END_PROGRAM
";
    let (trace, stderr) = run_text("tally.st", src, 3, "Main.r,Main.n");
    assert!(!stderr.contains("error"), "{stderr}");
    assert_eq!(column(&trace, "Main.r"), [2.0, 2.0, 2.0], "{trace}");
    assert_eq!(column(&trace, "Main.n"), [1.0, 2.0, 3.0], "{trace}");
}

/// A function the project does not have, called many times in one POU, is one E1019 there, at its
/// first call (before: one per call, 104 for a missing Tc2_Utilities `F_ToCHR` in a real
/// TwinCAT project, which hid the errors naming its missing library blocks); a second POU
/// calling it has its own.
#[test]
fn an_unknown_function_is_one_error_per_pou() {
    let src = "PROGRAM Main
VAR s : STRING; a, b : INT; END_VAR
s := Lib_ToChr(65);
s := CONCAT(Lib_ToChr(66), Lib_ToChr(67));
IF a > 0 THEN s := Lib_ToChr(a); END_IF
END_PROGRAM
FUNCTION_BLOCK FB_Other
VAR s : STRING; END_VAR
s := Lib_ToChr(68);
s := Lib_ToChr(69);
END_FUNCTION_BLOCK
";
    let (code, lines) = check_text("chr.st", src);
    assert_eq!(code, Some(1));
    let e: Vec<_> = lines.iter().filter(|l| l.contains("E1019")).collect();
    assert_eq!(e.len(), 2, "{lines:?}");
    assert!(e[0].starts_with("chr.st:3:6:"), "{lines:?}");
    assert!(e[1].starts_with("chr.st:9:6:"), "{lines:?}");
}

/// A solution of two PLC projects, A and B, whose `.tsproj` links NC axes T and X to B's
/// `MAIN.T` and `MAIN.X` (`<OwnerA Name="TIPC^B^B Instance">`): compiling A reads only A's
/// instance's links, so A's `MAIN.X` links to axis X by name and moves it (before: B's links were
/// applied to A too, E1057 "axis `T` links `MAIN.T`, which is no AXIS_REF of the program";
/// Tembo-PickupAutomatisation's "Motor test" and "Pneumatiek test"). B still has its own links.
#[test]
fn a_solutions_links_belong_to_their_own_plc_project() {
    let dir = tempfile::tempdir().unwrap();
    write_in(dir.path(), "Sol/Sol.tsproj", TSPROJ);
    write_in(dir.path(), "Sol/A/A.plcproj", A_PLCPROJ);
    write_in(dir.path(), "Sol/A/POUs/MAIN.TcPOU", A_MAIN);
    write_in(
        dir.path(),
        "Sol/B/B.plcproj",
        &A_PLCPROJ.replace(">A<", ">B<"),
    );
    write_in(dir.path(), "Sol/B/POUs/MAIN.TcPOU", B_MAIN);
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "Sol/A/A.plcproj",
            "--cycles",
            "100",
            "--trace",
            "-",
            "--watch",
            "MAIN.fbMove.Done,axis.X.position",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "MAIN.fbMove.Done")[99], 1.0, "{trace}");
    assert!(
        (column(&trace, "axis.X.position")[99] - 100.0).abs() < 1e-9,
        "{trace}"
    );
    // B's program links both of its axes (no E1057, both powered)
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "Sol/B/B.plcproj",
            "--cycles",
            "5",
            "--trace",
            "-",
            "--watch",
            "MAIN.pX.Status,MAIN.pT.Status",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "MAIN.pT.Status")[4], 1.0, "{trace}");
}

const TSPROJ: &str = r##"<?xml version="1.0"?>
<TcSmProject TcSmVersion="1.0" TcVersion="3.1.4024.12">
	<Project ProjectGUID="{00000000-0000-0000-0000-00000000AAAA}" Target64Bit="true" ShowHideConfigurations="#x6">
		<Motion>
			<NC>
				<Task Id="3" Priority="4" CycleTime="20000" AmsPort="501">
					<Name>NC-Task 1 SAF</Name>
				</Task>
				<Axes>
					<Axis Id="1" CreateSymbols="true" AxisType="1">
						<Name>X</Name>
						<AxisPara>
							<Dynamic Acceleration="1000" Deceleration="1000" Jerk="10000"/>
							<Velo Maximum="500"/>
						</AxisPara>
					</Axis>
					<Axis Id="2" CreateSymbols="true" AxisType="1">
						<Name>T</Name>
						<AxisPara>
							<Dynamic Acceleration="1000" Deceleration="1000" Jerk="10000"/>
							<Velo Maximum="500"/>
						</AxisPara>
					</Axis>
				</Axes>
			</NC>
		</Motion>
		<Plc>
			<Project GUID="{00000000-0000-0000-0000-00000000000A}" Name="A" PrjFilePath="A\A.plcproj" TmcFilePath="A\A.tmc" AmsPort="851">
				<Instance Id="#x08502000" TcSmClass="TComPlcObjDef" KeepUnrestoredLinks="2"><Name>A Instance</Name></Instance>
			</Project>
			<Project GUID="{00000000-0000-0000-0000-00000000000B}" Name="B" PrjFilePath="B\B.plcproj" TmcFilePath="B\B.tmc" AmsPort="852">
				<Instance Id="#x08502040" TcSmClass="TComPlcObjDef" KeepUnrestoredLinks="2"><Name>B Instance</Name></Instance>
			</Project>
		</Plc>
	</Project>
	<Mappings>
		<OwnerA Name="TIPC^B^B Instance">
			<OwnerB Name="TINC^NC-Task 1 SAF^Axes^T">
				<Link VarA="PlcTask Inputs^MAIN.T.NcToPlc" VarB="Outputs^ToPlc"/>
				<Link VarA="PlcTask Outputs^MAIN.T.PlcToNc" VarB="Inputs^FromPlc"/>
			</OwnerB>
			<OwnerB Name="TINC^NC-Task 1 SAF^Axes^X">
				<Link VarA="PlcTask Inputs^MAIN.X.NcToPlc" VarB="Outputs^ToPlc"/>
				<Link VarA="PlcTask Outputs^MAIN.X.PlcToNc" VarB="Inputs^FromPlc"/>
			</OwnerB>
		</OwnerA>
	</Mappings>
</TcSmProject>"##;

const A_PLCPROJ: &str = r##"<?xml version="1.0" encoding="utf-8"?>
<Project DefaultTargets="Build" xmlns="http://schemas.microsoft.com/developer/msbuild/2003">
  <PropertyGroup>
    <Name>A</Name>
    <ProjectGuid>{00000000-0000-0000-0000-00000000000A}</ProjectGuid>
  </PropertyGroup>
  <ItemGroup>
    <Compile Include="POUs\MAIN.TcPOU">
      <SubType>Code</SubType>
    </Compile>
  </ItemGroup>
</Project>"##;

const A_MAIN: &str = r##"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="MAIN" Id="{00000000-0000-0000-0000-0000000000A1}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	X : AXIS_REF;
	fbPower : MC_Power;
	fbMove : MC_MoveAbsolute;
END_VAR]]></Declaration>
    <Implementation>
      <ST><![CDATA[fbPower(Axis := X, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
fbMove(Axis := X, Execute := fbPower.Status, Position := 100, Velocity := 200);]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>"##;

const B_MAIN: &str = r##"<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1" ProductVersion="3.1.4024.12">
  <POU Name="MAIN" Id="{00000000-0000-0000-0000-0000000000B1}" SpecialFunc="None">
    <Declaration><![CDATA[PROGRAM MAIN
VAR
	X : AXIS_REF;
	T : AXIS_REF;
	pX : MC_Power;
	pT : MC_Power;
END_VAR]]></Declaration>
    <Implementation>
      <ST><![CDATA[pX(Axis := X, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);
pT(Axis := T, Enable := TRUE, Enable_Positive := TRUE, Enable_Negative := TRUE);]]></ST>
    </Implementation>
  </POU>
</TcPlcObject>"##;

/// A `.TcPOU` whose declaration starts with a nested comment (a version-history header `(*===`
/// / `(* v1.2 *)` / `===*)`, as Beckhoff's SA0163 shows compiling) is read as the block it
/// declares (before: E0321 "its <Declaration> does not begin with PROGRAM, FUNCTION_BLOCK or
/// FUNCTION": the pre-check ended the comment at the first `*)`).
#[test]
fn a_nested_comment_before_the_block_keyword_of_a_tcpou() {
    let dir = tempfile::tempdir().unwrap();
    let pou = |name: &str, decl: &str, body: &str| {
        format!(
            "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<TcPlcObject Version=\"1.1.0.1\">\n  <POU Name=\"{name}\" Id=\"{{00000000-0000-0000-0000-000000000001}}\">\n    <Declaration><![CDATA[{decl}]]></Declaration>\n    <Implementation>\n      <ST><![CDATA[{body}]]></ST>\n    </Implementation>\n  </POU>\n</TcPlcObject>\n"
        )
    };
    write_in(
        dir.path(),
        "FB_Avg.TcPOU",
        &pou(
            "FB_Avg",
            "(*=====\n(* v1.2: doubled *)\nstill the header *)\nFUNCTION_BLOCK FB_Avg\nVAR_INPUT x : INT; END_VAR\nVAR_OUTPUT y : INT; END_VAR",
            "y := x * 2;",
        ),
    );
    write_in(
        dir.path(),
        "MAIN.TcPOU",
        &pou(
            "MAIN",
            "PROGRAM MAIN\nVAR f : FB_Avg; r : INT; END_VAR",
            "f(x := 21);\nr := f.y;",
        ),
    );
    let (code, trace, stderr) = in_dir(
        dir.path(),
        &[
            "run",
            "MAIN.TcPOU",
            "FB_Avg.TcPOU",
            "--cycles",
            "1",
            "--trace",
            "-",
            "--watch",
            "MAIN.r",
        ],
    );
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(column(&trace, "MAIN.r"), [42.0], "{trace}");
}

/// A project's FUNCTION_BLOCK named `TON` (ControlForge's interface stubs of the standard blocks)
/// replaces the standard timer in the whole project, as in CODESYS: W1446 says so at its name
/// (before: silent, and the stub's `Q` stayed FALSE with no hint why).
#[test]
fn a_block_named_as_a_standard_block_is_w1446() {
    let src = "FUNCTION_BLOCK TON
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
Q := IN;
END_FUNCTION_BLOCK
PROGRAM Main
VAR t : TON; q : BOOL; END_VAR
t(IN := TRUE, PT := T#30ms);
q := t.Q;
END_PROGRAM
";
    let (code, lines) = check_text("stubs.st", src);
    assert_eq!(code, Some(0), "{lines:?}");
    assert_eq!(lines.len(), 1, "{lines:?}");
    assert!(
        lines[0].starts_with("stubs.st:1:16: warning[W1446]"),
        "{lines:?}"
    );
    // the project's block runs: Q follows IN at once (the standard TON would wait 30 ms)
    let (trace, _) = run_text("stubs.st", src, 1, "Main.q");
    assert_eq!(column(&trace, "Main.q"), [1.0], "{trace}");
}

/// B&R's system libraries given with a program (`Logical/Libraries/operator/operator.fun` declares
/// ADD, `standard.fun` TON, without statements): not compiled, one note W0021 per file, and
/// ladderc's own ADD and TON run (before: ADD was a user FUNCTION with an ANY input, E1068 at
/// each call, and in a whole project an unbounded rewrite overflowed the stack; the TON an empty
/// block that never timed). A declared block no file implements is E1019 where it is called.
#[test]
fn a_br_system_librarys_declarations_leave_the_standard_blocks_in_place() {
    let dir = tempfile::tempdir().unwrap();
    write_in(
        dir.path(),
        "Libraries/operator/operator.fun",
        "{REDUND_OK} FUNCTION ADD : ANY\n\tVAR_INPUT\n\t\tINx\t:ANY;\n\tEND_VAR\nEND_FUNCTION\n\
         {REDUND_OK} FUNCTION SIZEOF : UDINT\n\tVAR_INPUT\n\t\tin\t:ANY;\n\tEND_VAR\nEND_FUNCTION\n",
    );
    write_in(
        dir.path(),
        "Libraries/standard/standard.fun",
        "FUNCTION_BLOCK TON\n\tVAR_INPUT IN : BOOL; PT : TIME; END_VAR\n\tVAR_OUTPUT Q : BOOL; ET : TIME; END_VAR\nEND_FUNCTION_BLOCK\n\
         FUNCTION Vendor_Only : INT\n\tVAR_INPUT a : INT; END_VAR\nEND_FUNCTION\n",
    );
    write_in(
        dir.path(),
        "Main/Main.st",
        "PROGRAM Main\nVAR x : INT; t : TON; q : BOOL; n : UDINT; END_VAR\nx := ADD(1, 2);\n\
         n := SIZEOF(x);\nt(IN := TRUE, PT := T#20ms);\nq := t.Q;\nEND_PROGRAM\n",
    );
    let files = [
        "Libraries/operator/operator.fun",
        "Libraries/standard/standard.fun",
        "Main/Main.st",
    ];
    let mut args = vec!["run", "--lang", "st"];
    args.extend(files);
    args.extend([
        "--cycles",
        "4",
        "--trace",
        "-",
        "--watch",
        "Main.x,Main.n,Main.q",
    ]);
    let (code, trace, stderr) = in_dir(dir.path(), &args);
    assert_eq!(code, Some(0), "{stderr}");
    assert_eq!(stderr.matches("W0021").count(), 2, "{stderr}");
    assert!(
        stderr.contains("declares 2 block(s) that no file implements (`TON`, `Vendor_Only`)"),
        "{stderr}"
    );
    assert_eq!(column(&trace, "Main.x"), [3.0; 4], "{trace}");
    assert_eq!(column(&trace, "Main.n"), [2.0; 4], "{trace}");
    // the standard TON: Q after 20 ms
    assert_eq!(column(&trace, "Main.q"), [0.0, 0.0, 1.0, 1.0], "{trace}");
    // a call of the library's own function: E1019 at the call
    write_in(
        dir.path(),
        "Main/Main.st",
        "PROGRAM Main\nVAR y : INT; END_VAR\ny := Vendor_Only(3);\nEND_PROGRAM\n",
    );
    let mut args = vec!["check", "--lang", "st"];
    args.extend(files);
    let (code, _, stderr) = in_dir(dir.path(), &args);
    assert_eq!(code, Some(1), "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.contains("error[")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].starts_with("Main/Main.st:3:6: error[E1019]"),
        "{stderr}"
    );
}

/// A project's own FUNCTION named SIZEOF with an ANY input, called with the hidden inputs the
/// rewrite of another ANY call adds: the rewrite ends (before: it gave its own `SIZEOF(x)`
/// hidden inputs again without end, and overflowed the stack); located errors, exit 1.
#[test]
fn a_function_named_sizeof_with_an_any_input_does_not_loop() {
    let src = "FUNCTION SIZEOF : UDINT
VAR_INPUT in : ANY; END_VAR
SIZEOF := 4;
END_FUNCTION
FUNCTION F : UDINT
VAR_INPUT x : ANY; END_VAR
F := x.diSize;
END_FUNCTION
PROGRAM Main
VAR a : INT; r : UDINT; END_VAR
r := F(a);
END_PROGRAM
";
    let (code, lines) = check_text("loop.st", src);
    assert_eq!(code, Some(1), "{lines:?}");
    assert!(!lines.is_empty());
    assert!(lines.iter().all(|l| l.starts_with("loop.st:")), "{lines:?}");
}

/// `MEMCPY(ADR(buf), blockInfo.pData + 4, ...)` where `blockInfo` is undeclared: E1001 names it,
/// and the other undeclared names of the project are reported too (before: one E1035 "the
/// variable this pointer points into cannot be known", which stopped every other check: Yaha
/// BMS's 10 E1001 appeared only once its MEMCPY lines were removed). A POINTER TO variable plus
/// a byte offset is its address moved on (`p + 4` of an INT array: the third element).
#[test]
fn memcpy_of_a_pointer_expression_names_what_is_undeclared() {
    let src = "PROGRAM Main
VAR buf : ARRAY[0..3] OF INT; END_VAR
MEMCPY(ADR(buf), blockInfo.pData + 4, SIZEOF(buf));
counter := counter + 1;
END_PROGRAM
";
    let (code, lines) = check_text("mem.st", src);
    assert_eq!(code, Some(1));
    assert_eq!(lines.len(), 2, "{lines:?}");
    assert!(
        lines[0].starts_with("mem.st:3:18: error[E1001]: undeclared name `blockInfo`"),
        "{lines:?}"
    );
    assert!(
        lines[1].starts_with("mem.st:4:12: error[E1001]: undeclared name `counter`"),
        "{lines:?}"
    );
    let src = "PROGRAM Main
VAR
  buf : ARRAY[0..3] OF INT;
  src : ARRAY[0..7] OF INT := [1, 2, 3, 4, 5, 6, 7, 8];
  p : POINTER TO INT;
  n, m : INT;
END_VAR
p := ADR(src);
MEMCPY(ADR(buf), p + 4, SIZEOF(buf));
n := buf[0];
m := buf[3];
END_PROGRAM
";
    let (trace, stderr) = run_text("ptr.st", src, 1, "Main.n,Main.m");
    assert!(!stderr.contains("runtime"), "{stderr}");
    assert_eq!(column(&trace, "Main.n"), [3.0], "{trace}");
    assert_eq!(column(&trace, "Main.m"), [6.0], "{trace}");
}
