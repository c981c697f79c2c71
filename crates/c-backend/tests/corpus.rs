//! Real IL from the corpus (GPL: read from `$LADDERC_CORPUS`, never copied; skipped when it is unset),
//! completed by a small driver program, through the whole chain.

mod support;
use support::*;

fn corpus_with_driver(file: &str, driver: &str) -> Option<Built> {
    let text = std::fs::read_to_string(corpus(file)?).expect("corpus file");
    Some(build_src(&format!("{text}\n{driver}")))
}

#[test]
fn annex_f_cmd_monitor_raises_and_acknowledges_its_alarm() {
    let Some(b) = corpus_with_driver(
        "il/17_matiec_AnnexF_cmd_monitor_il.st",
        "PROGRAM main
VAR
  mon : CMD_MONITOR;
END_VAR
  CAL mon(AUTO_CMD := %IX0.0, AUTO_MODE := %IX0.1, MAN_CMD := FALSE, MAN_CMD_CHK := FALSE,
          T_CMD_MAX := T#30ms, FDBK := %IX0.2, ACK := %IX0.3)
  LD mon.CMD
  ST %QX0.0
  LD mon.ALRM
  ST %QX0.1
END_PROGRAM
",
    ) else {
        return;
    };
    // cycle 1: automatic command; no feedback within 30 ms -> alarm at cycle 4;
    // ACK at cycle 6 while the command is still on does not cancel (S1 dominates);
    // command off at cycle 8, ACK at cycle 9 cancels
    let stim = "1,%IX0.1,1\n1,%IX0.0,1\n6,%IX0.3,1\n7,%IX0.3,0\n8,%IX0.0,0\n9,%IX0.3,1\n";
    let rows = run(&b, 11, 10.0, stim, &["%QX0.0", "%QX0.1"]);
    assert_eq!(
        column(&rows, "%QX0.0"),
        ["0", "1", "1", "1", "1", "1", "1", "1", "0", "0", "0"]
    );
    assert_eq!(
        column(&rows, "%QX0.1"),
        ["0", "0", "0", "0", "1", "1", "1", "1", "1", "0", "0"]
    );
}

#[test]
fn annex_f_weigh_function_decodes_bcd_and_returns_early_without_command() {
    let Some(b) = corpus_with_driver(
        "il/17_matiec_AnnexF_weigh_il.st",
        "PROGRAM main
VAR
  net : WORD;
END_VAR
  WEIGH(weigh_command := %IX0.0, gross_weight := %IW1, tare_weight := 20)
  ST net
END_PROGRAM
",
    ) else {
        return;
    };
    // gross 150 in BCD (16#0150 = 336), tare 20: net 130 in BCD (16#0130 = 304)
    let stim = "0,%IW1,336\n1,%IX0.0,1\n";
    let rows = run(&b, 2, 10.0, stim, &["main.net"]);
    assert_eq!(column(&rows, "main.net"), ["0", "304"]);
}

#[test]
fn strucpp_state_display_lights_one_led_per_state() {
    let Some(b) = corpus_with_driver(
        "il/20_strucpp_state-display.il",
        "PROGRAM main
VAR
  disp : State_Display;
  s : INT;
END_VAR
  CAL disp(State := s)
  LD disp.Stopped_led
  ST %QX0.0
  LD disp.Running_led
  ST %QX0.1
  LD disp.Manual_led
  ST %QX0.2
END_PROGRAM
",
    ) else {
        return;
    };
    let stim = "0,main.s,0\n1,main.s,1\n2,main.s,2\n3,main.s,7\n";
    let rows = run(&b, 4, 10.0, stim, &["%QX0.0", "%QX0.1", "%QX0.2"]);
    assert_eq!(column(&rows, "%QX0.0"), ["1", "0", "0", "0"]);
    assert_eq!(column(&rows, "%QX0.1"), ["0", "1", "0", "0"]);
    assert_eq!(column(&rows, "%QX0.2"), ["0", "0", "1", "1"]);
}
