//! Streaming into a rotary buffer: the file transport's text, and the TCP line protocol against a loopback
//! simulator (127.0.0.1, ephemeral port, bounded loops and timeouts; it ends when the client disconnects).
//!
//! The simulator follows the documented protocol: banner "STDIN Open for ASCII Input"; lines between
//! `OPEN ROT`/`open rotary` and `CLOSE` are buffer lines, whatever they say (as on a Turbo PMAC, an
//! on-line command sent to an open buffer is entered into it); `PR` is answered (after an echo and an ACK) with the
//! unexecuted line count; once started (`&1 R` with the buffer closed) it executes `drain` lines per `PR` (only every
//! `drain_every`-th `PR`, to make the host wait); an injected bad line gets `stdin:N:1: error #21: ILLEGAL CMD`.

mod common;

use common::{cs, sampled, stop_move};
use pmac_backend::model::Dialect;
use pmac_backend::pvt::{self, PvtOptions, PvtSegment, StreamOptions};
use pmac_backend::transport::{FileTransport, GpasciiOptions, GpasciiTcp};
use std::io::{BufRead, BufReader, Write};
use std::net::{SocketAddr, TcpListener};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

#[derive(Clone)]
struct Sim {
    banner: bool,
    capacity: usize,
    drain: usize,
    drain_every: usize,
    error_at: Option<usize>,
}

#[derive(Default, Debug)]
struct Log {
    setup: Vec<String>,
    content: Vec<String>,
    max_fill: usize,
    overflow: bool,
    started_after: Option<usize>,
    closed_after: Option<usize>,
    aborted: bool,
    after_error: usize,
}

fn spawn(sim: Sim) -> (SocketAddr, JoinHandle<Log>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = listener.local_addr().unwrap();
    let handle = std::thread::spawn(move || {
        let mut log = Log::default();
        listener.set_nonblocking(true).unwrap();
        let deadline = Instant::now() + Duration::from_secs(10);
        let sock = loop {
            match listener.accept() {
                Ok((s, _)) => break s,
                Err(_) if Instant::now() < deadline => std::thread::sleep(Duration::from_millis(2)),
                Err(_) => return log,
            }
        };
        sock.set_nonblocking(false).unwrap();
        sock.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
        let mut out = sock.try_clone().unwrap();
        if sim.banner {
            out.write_all(b"gpascii -2\r\nSTDIN Open for ASCII Input\r\n")
                .unwrap();
        }
        let mut reader = BufReader::new(sock);
        let (mut open, mut running, mut fill, mut polls) = (false, false, 0usize, 0usize);
        let mut error_sent = false;
        for _ in 0..100_000 {
            let mut line = String::new();
            match reader.read_line(&mut line) {
                Ok(0) | Err(_) => break,
                Ok(_) => {}
            }
            let upper = line.trim().to_ascii_uppercase();
            if error_sent && upper != "PR" {
                log.after_error += 1;
            }
            if upper == "PR" {
                polls += 1;
                if running && polls % sim.drain_every == 0 {
                    fill -= fill.min(sim.drain);
                }
                let _ = out.write_all(format!("PR\r\n{fill}\r\n\x06").as_bytes());
            } else if upper == "OPEN ROT" || upper == "OPEN ROTARY" {
                open = true;
            } else if upper == "CLOSE" {
                open = false;
                log.closed_after = Some(log.content.len());
            } else if open {
                // Like a Turbo PMAC: while the buffer is open, every other line is a buffer line, even an
                // on-line command such as `&1 B0 R` (a B-axis move) or `&1 A` (an A-axis move).
                log.content.push(line.trim().to_string());
                fill += 1;
                log.max_fill = log.max_fill.max(fill);
                log.overflow |= fill > sim.capacity;
                if sim.error_at == Some(log.content.len()) {
                    let _ = out.write_all(
                        format!("stdin:{}:1: error #21: ILLEGAL CMD\r\n", log.content.len())
                            .as_bytes(),
                    );
                    error_sent = true;
                }
            } else if upper == "&1 R" || upper == "&1 B0 R" {
                running = true;
                log.started_after.get_or_insert(log.content.len());
            } else if upper == "&1 A" {
                log.aborted = true;
            } else {
                log.setup.push(line.trim().to_string());
            }
        }
        log
    });
    (addr, handle)
}

fn short_segments() -> Vec<PvtSegment> {
    // 0.2 x 0.1 units, v 1, a 10, j 100: 0.4 s, 40 segments of 10 ms.
    let input = sampled(&[stop_move(vec![0.2, 0.1], 1.0, 10.0, 100.0)], 0.001);
    pvt::segments(&input, 0.01).unwrap()
}

fn tcp_opts(capacity: usize) -> GpasciiOptions {
    GpasciiOptions {
        capacity_lines: capacity,
        timeout: Duration::from_secs(2),
        poll_interval: Duration::from_millis(1),
        ..GpasciiOptions::default()
    }
}

#[test]
fn streams_every_line_without_overfilling_the_buffer() {
    let sim = Sim {
        banner: true,
        capacity: 8,
        drain: 3,
        drain_every: 2,
        error_at: None,
    };
    let (addr, server) = spawn(sim);
    let segs = short_segments();
    let c = cs(&['X', 'Y']);
    let expected = pvt::to_lines(&c, &segs, &PvtOptions::default()).unwrap();
    let mut t = GpasciiTcp::connect(addr, tcp_opts(8)).unwrap();
    let report = pvt::stream(
        &c,
        &segs,
        &PvtOptions::default(),
        &StreamOptions::default(),
        &mut t,
    )
    .unwrap();
    drop(t);
    let log = server.join().unwrap();
    assert_eq!(log.content, expected, "every buffer line arrives, in order");
    assert!(!log.overflow && log.max_fill <= 8, "{log:?}");
    assert_eq!(
        log.max_fill, 8,
        "the host fills the buffer up to its capacity"
    );
    assert_eq!(
        log.started_after,
        Some(8),
        "the program starts once the buffer is primed"
    );
    assert_eq!(log.closed_after, Some(expected.len()));
    assert_eq!(
        log.setup,
        [
            "DELETE GATHER",
            "I5190=1000",
            "&1 #1->1000X #2->1000Y",
            "&1 DEFINE ROT 2048",
            "&1 B0"
        ]
    );
    assert_eq!(report.started_after, Some(8));
    assert_eq!(report.lines_sent, expected.len());
    assert_eq!(report.peak_fill, 8);
    assert!(
        report.full_waits > 0,
        "every other poll finds the buffer still full: {report:?}"
    );
    assert!(!log.aborted);
}

#[test]
fn an_error_reply_stops_the_stream_and_aborts() {
    let sim = Sim {
        banner: true,
        capacity: 8,
        drain: 4,
        drain_every: 1,
        error_at: Some(12),
    };
    let (addr, server) = spawn(sim);
    let segs = short_segments();
    let c = cs(&['X', 'Y']);
    let total = pvt::to_lines(&c, &segs, &PvtOptions::default())
        .unwrap()
        .len();
    let mut t = GpasciiTcp::connect(addr, tcp_opts(8)).unwrap();
    let err = pvt::stream(
        &c,
        &segs,
        &PvtOptions::default(),
        &StreamOptions::default(),
        &mut t,
    )
    .unwrap_err();
    drop(t);
    let log = server.join().unwrap();
    assert_eq!(err.code(), "E7004");
    assert!(
        err.diagnostic()
            .message
            .contains("stdin:12:1: error #21: ILLEGAL CMD"),
        "{err}"
    );
    assert!(log.aborted, "the coordinate system is aborted");
    assert!(log.closed_after.is_some(), "the buffer is closed");
    // Nothing after the next poll: at most one buffer's worth of lines followed the bad one.
    assert!(
        log.content.len() < total && log.content.len() <= 12 + 8,
        "{} lines",
        log.content.len()
    );
    assert!(log.after_error <= 8 + 2, "{log:?}");
}

#[test]
fn a_stuck_buffer_times_out() {
    let sim = Sim {
        banner: true,
        capacity: 4,
        drain: 0,
        drain_every: 1,
        error_at: None,
    };
    let (addr, server) = spawn(sim);
    let mut t = GpasciiTcp::connect(addr, tcp_opts(4)).unwrap();
    let opts = StreamOptions {
        max_full_polls: 5,
        ..StreamOptions::default()
    };
    let c = cs(&['X', 'Y']);
    let err =
        pvt::stream(&c, &short_segments(), &PvtOptions::default(), &opts, &mut t).unwrap_err();
    drop(t);
    let log = server.join().unwrap();
    assert_eq!(err.code(), "E7005");
    assert!(err.diagnostic().message.contains("stayed full"), "{err}");
    assert_eq!(log.content.len(), 4);
    assert!(!log.overflow);
}

#[test]
fn a_silent_controller_times_out() {
    let sim = Sim {
        banner: false,
        capacity: 4,
        drain: 1,
        drain_every: 1,
        error_at: None,
    };
    let (addr, server) = spawn(sim);
    let started = Instant::now();
    let opts = GpasciiOptions {
        timeout: Duration::from_millis(200),
        ..tcp_opts(4)
    };
    let err = GpasciiTcp::connect(addr, opts).err().expect("no banner");
    assert_eq!(err.code(), "E7005");
    assert!(err.diagnostic().message.contains("banner"), "{err}");
    assert!(started.elapsed() < Duration::from_secs(2));
    server.join().unwrap();
}

#[test]
fn refused_connection_is_a_transport_error() {
    // Bind then drop a listener: the port is (almost certainly) closed now.
    let addr = TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap();
    let err = GpasciiTcp::connect(addr, tcp_opts(4))
        .err()
        .expect("refused");
    assert_eq!(err.code(), "E7005");
}

#[test]
fn file_transport_writes_the_whole_script() {
    let c = cs(&['X', 'Y']);
    let segs = short_segments();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("out.pmc");
    let mut t = FileTransport::create(&path).unwrap();
    let report = pvt::stream(
        &c,
        &segs,
        &PvtOptions::default(),
        &StreamOptions::default(),
        &mut t,
    )
    .unwrap();
    drop(t);
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(report.polls, 0);
    assert_eq!(report.lines_sent, segs.len() + 2);
    insta::assert_snapshot!("short_move_rotary_turbo_file", text);
    let mut mem = FileTransport::new(Vec::new());
    let power = PvtOptions {
        dialect: Dialect::Power,
        ..PvtOptions::default()
    };
    pvt::stream(
        &c,
        &segs[segs.len() - 3..],
        &power,
        &StreamOptions::default(),
        &mut mem,
    )
    .unwrap();
    insta::assert_snapshot!(
        "rotary_power_tail",
        String::from_utf8(mem.into_inner()).unwrap()
    );
}

#[test]
fn file_transport_reports_unwritable_paths() {
    let dir = tempfile::tempdir().unwrap();
    let err = FileTransport::create(&dir.path().join("missing/dir/out.pmc"))
        .err()
        .unwrap();
    assert_eq!(err.code(), "E7005");
}

#[test]
fn write_file_is_the_streamed_script() {
    let input = sampled(&[stop_move(vec![0.2, 0.1], 1.0, 10.0, 100.0)], 0.001);
    let c = cs(&['X', 'Y']);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("pvt.pmc");
    let report = pvt::write_file(&c, &input, &PvtOptions::default(), &path).unwrap();
    let mut mem = FileTransport::new(Vec::new());
    pvt::stream(
        &c,
        &short_segments(),
        &PvtOptions::default(),
        &StreamOptions::default(),
        &mut mem,
    )
    .unwrap();
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        String::from_utf8(mem.into_inner()).unwrap()
    );
    assert_eq!(report.lines_sent, 42);
}
