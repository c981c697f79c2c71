//! The Turbo PMAC Ethernet transport (8-byte ETHERNETCMD packets) against a loopback simulator that follows
//! the documented behaviour: FLUSH is answered by one byte; each VR_PMAC_GETRESPONSE line is answered by ACK,
//! `PR` by `<count><CR><ACK>`, an injected bad line by `<BELL>ERR003<CR>`. The simulator checks every header
//! (request type 0x40, request code, wValue = wIndex = 0, big-endian wLength equal to the data length).

mod common;

use common::{cs, sampled, stop_move};
use pmac_backend::pvt::{self, PvtOptions, StreamOptions};
use pmac_backend::transport::{turbo_eth, TurboEthernet, TurboEthernetOptions};
use std::io::{Read, Write};
use std::net::{SocketAddr, TcpListener};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

#[derive(Default, Debug)]
struct Log {
    lines: Vec<String>,
    content: usize,
    max_fill: usize,
    overflow: bool,
    bad_header: bool,
    flushed: bool,
    aborted: bool,
    started_after: Option<usize>,
}

fn spawn(capacity: usize, drain: usize, error_at: Option<usize>) -> (SocketAddr, JoinHandle<Log>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = listener.local_addr().unwrap();
    let h = std::thread::spawn(move || {
        let mut log = Log::default();
        listener.set_nonblocking(true).unwrap();
        let deadline = Instant::now() + Duration::from_secs(10);
        let mut sock = loop {
            match listener.accept() {
                Ok((s, _)) => break s,
                Err(_) if Instant::now() < deadline => std::thread::sleep(Duration::from_millis(2)),
                Err(_) => return log,
            }
        };
        sock.set_nonblocking(false).unwrap();
        sock.set_read_timeout(Some(Duration::from_secs(5))).unwrap();
        let (mut open, mut running, mut fill) = (false, false, 0usize);
        for _ in 0..100_000 {
            let mut head = [0u8; 8];
            if sock.read_exact(&mut head).is_err() {
                break;
            }
            let len = u16::from_be_bytes([head[6], head[7]]) as usize;
            let mut data = vec![0u8; len];
            if sock.read_exact(&mut data).is_err() {
                break;
            }
            log.bad_header |= head[0] != turbo_eth::VR_DOWNLOAD || head[2..6] != [0, 0, 0, 0];
            if head[1] == turbo_eth::VR_PMAC_FLUSH {
                log.flushed = true;
                sock.write_all(&[turbo_eth::VR_DOWNLOAD]).unwrap();
                continue;
            }
            log.bad_header |=
                head[1] != turbo_eth::VR_PMAC_GETRESPONSE || data.last() != Some(&b'\r');
            let line = String::from_utf8_lossy(&data).trim().to_string();
            log.lines.push(line.clone());
            let reply: Vec<u8> = match line.as_str() {
                "PR" => {
                    if running {
                        fill -= fill.min(drain);
                    }
                    format!("{fill}\r\x06").into_bytes()
                }
                "OPEN ROT" => {
                    open = true;
                    vec![turbo_eth::ACK]
                }
                "CLOSE" => {
                    open = false;
                    vec![turbo_eth::ACK]
                }
                // While the buffer is open every other line is a buffer line (`&1 B0 R` would be a B-axis
                // move, `&1 A` an A-axis move), as on a Turbo PMAC.
                "&1 R" if !open => {
                    running = true;
                    log.started_after.get_or_insert(log.content);
                    vec![turbo_eth::ACK]
                }
                "&1 A" if !open => {
                    log.aborted = true;
                    vec![turbo_eth::ACK]
                }
                _ if open => {
                    log.content += 1;
                    fill += 1;
                    log.max_fill = log.max_fill.max(fill);
                    log.overflow |= fill > capacity;
                    if error_at == Some(log.content) {
                        b"\x07ERR003\r".to_vec()
                    } else {
                        vec![turbo_eth::ACK]
                    }
                }
                _ => vec![turbo_eth::ACK],
            };
            sock.write_all(&reply).unwrap();
        }
        log
    });
    (addr, h)
}

fn opts(capacity: usize) -> TurboEthernetOptions {
    TurboEthernetOptions {
        capacity_lines: capacity,
        timeout: Duration::from_secs(2),
        poll_interval: Duration::from_millis(1),
        ..TurboEthernetOptions::default()
    }
}

#[test]
fn streams_pvt_over_turbo_ethernet() {
    let input = sampled(&[stop_move(vec![0.2, 0.1], 1.0, 10.0, 100.0)], 0.001);
    let segs = pvt::segments(&input, 0.01).unwrap();
    let c = cs(&['X', 'Y']);
    let expected = pvt::to_lines(&c, &segs, &PvtOptions::default()).unwrap();
    let (addr, server) = spawn(6, 2, None);
    let mut t = TurboEthernet::connect(addr, opts(6)).unwrap();
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
    assert!(log.flushed && !log.bad_header, "{log:?}");
    assert_eq!(log.content, expected.len());
    assert!(!log.overflow && log.max_fill == 6, "{log:?}");
    let sent: Vec<&String> = log.lines.iter().filter(|l| *l != "PR").collect();
    assert_eq!(
        sent[..7],
        [
            "CLOSE",
            "DELETE GATHER",
            "I5190=1000",
            "&1 #1->1000X #2->1000Y",
            "&1 DEFINE ROT 2048",
            "&1 B0",
            "OPEN ROT"
        ]
    );
    assert_eq!(
        log.started_after,
        Some(6),
        "started once the look-ahead is in"
    );
    assert_eq!(sent.last().unwrap().as_str(), "CLOSE");
    assert_eq!(report.lines_sent, expected.len());
    // Once full, each poll frees 2 lines: at least (lines - capacity) / 2 polls.
    assert!(report.polls >= (expected.len() - 6) / 2, "{report:?}");
}

#[test]
fn bell_error_stops_at_the_bad_line() {
    let input = sampled(&[stop_move(vec![0.2, 0.1], 1.0, 10.0, 100.0)], 0.001);
    let segs = pvt::segments(&input, 0.01).unwrap();
    let c = cs(&['X', 'Y']);
    let (addr, server) = spawn(6, 2, Some(5));
    let mut t = TurboEthernet::connect(addr, opts(6)).unwrap();
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
    assert!(err.diagnostic().message.contains("ERR003"), "{err}");
    assert_eq!(log.content, 5, "nothing is sent after the bad line");
    assert!(log.aborted);
    assert_eq!(&log.lines[log.lines.len() - 2..], ["CLOSE", "&1 A"]);
}

#[test]
fn packet_layout() {
    let p = turbo_eth::packet(
        turbo_eth::VR_DOWNLOAD,
        turbo_eth::VR_PMAC_GETRESPONSE,
        b"PR\r",
    );
    assert_eq!(p, [0x40, 0xBF, 0, 0, 0, 0, 0, 3, b'P', b'R', b'\r']);
}
