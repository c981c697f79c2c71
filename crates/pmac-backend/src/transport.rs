//! Transports that carry text lines to a PMAC: a file, and TCP to a Power PMAC `gpascii`-style line protocol.
//!
//! Input: lines without line ends; a lines-remaining query.
//! Output: the lines written (file) or sent (socket, `\n`-terminated); the controller's lines-remaining count.
//! Invariants: every wait is bounded (socket read timeout; the streamer bounds the number of polls). The TCP
//! protocol (documented in the crate README): on connect the controller sends a banner containing
//! "STDIN Open for ASCII Input"; the host sends lines; the query `PR` is answered by the number of unexecuted
//! lines in the rotary buffer; any reply line containing "error" (any case) is an error report (E7004);
//! other reply lines (echoes, blank lines, control characters such as ACK) are ignored.

use crate::error::PmacError;
use std::io::{BufRead, BufReader, Write};
use std::net::{TcpStream, ToSocketAddrs};
use std::time::Duration;

/// Where buffer lines go.
pub trait Transport {
    /// Sends one line (no line end).
    fn send(&mut self, line: &str) -> Result<(), PmacError>;
    /// Rotary buffer capacity in lines; `None` for a sink that never fills (a file).
    fn capacity(&self) -> Option<usize>;
    /// Unexecuted lines in the buffer (`PR`); also reports any error reply that arrived since the last query.
    fn lines_remaining(&mut self) -> Result<usize, PmacError>;
    /// Pause before polling a full buffer again.
    fn wait(&mut self);
    /// Pushes out anything buffered.
    fn flush(&mut self) -> Result<(), PmacError>;
}

/// Writes the lines to any writer (a `.pmc` file), one per line. Never full.
pub struct FileTransport<W: Write> {
    out: W,
}

impl<W: Write> FileTransport<W> {
    /// Lines go to `out`.
    pub fn new(out: W) -> Self {
        FileTransport { out }
    }
    /// The writer back.
    pub fn into_inner(self) -> W {
        self.out
    }
}

impl FileTransport<std::io::BufWriter<std::fs::File>> {
    /// Creates (truncates) the file at `path`.
    pub fn create(path: &std::path::Path) -> Result<Self, PmacError> {
        let f = std::fs::File::create(path)
            .map_err(|e| PmacError::transport(format!("cannot create {}: {e}", path.display())))?;
        Ok(FileTransport::new(std::io::BufWriter::new(f)))
    }
}

impl<W: Write> Transport for FileTransport<W> {
    fn send(&mut self, line: &str) -> Result<(), PmacError> {
        writeln!(self.out, "{line}").map_err(|e| PmacError::transport(format!("write failed: {e}")))
    }
    fn capacity(&self) -> Option<usize> {
        None
    }
    fn lines_remaining(&mut self) -> Result<usize, PmacError> {
        Ok(0)
    }
    fn wait(&mut self) {}
    fn flush(&mut self) -> Result<(), PmacError> {
        self.out
            .flush()
            .map_err(|e| PmacError::transport(format!("write failed: {e}")))
    }
}

/// Settings of the TCP line protocol.
#[derive(Debug, Clone, PartialEq)]
pub struct GpasciiOptions {
    /// Rotary buffer capacity in lines (what the controller was told to hold, e.g. with I17/I16 on Turbo).
    pub capacity_lines: usize,
    /// Read timeout for the banner and each reply.
    pub timeout: Duration,
    /// Pause between polls of a full buffer.
    pub poll_interval: Duration,
    /// The lines-remaining query.
    pub query: String,
    /// Text the banner must contain; empty = do not wait for a banner.
    pub banner: String,
    /// Reply lines to skip while waiting for a count before giving up.
    pub max_reply_lines: usize,
}

impl Default for GpasciiOptions {
    fn default() -> Self {
        GpasciiOptions {
            capacity_lines: 256,
            timeout: Duration::from_secs(5),
            poll_interval: Duration::from_millis(20),
            query: "PR".to_string(),
            banner: "STDIN Open for ASCII Input".to_string(),
            max_reply_lines: 100,
        }
    }
}

/// A TCP connection to a controller speaking the gpascii-style line protocol.
pub struct GpasciiTcp {
    reader: BufReader<TcpStream>,
    writer: std::io::BufWriter<TcpStream>,
    opts: GpasciiOptions,
}

fn io_err(what: &str, e: std::io::Error) -> PmacError {
    use std::io::ErrorKind::{TimedOut, WouldBlock};
    if matches!(e.kind(), TimedOut | WouldBlock) {
        PmacError::transport(format!("{what}: no reply within the timeout"))
    } else {
        PmacError::transport(format!("{what}: {e}"))
    }
}

impl GpasciiTcp {
    /// Connects and waits for the banner.
    pub fn connect(addr: impl ToSocketAddrs, opts: GpasciiOptions) -> Result<Self, PmacError> {
        let addrs: Vec<_> = addr
            .to_socket_addrs()
            .map_err(|e| io_err("resolve address", e))?
            .collect();
        let first = addrs
            .first()
            .ok_or_else(|| PmacError::transport("no address to connect to"))?;
        let stream = TcpStream::connect_timeout(first, opts.timeout)
            .map_err(|e| io_err(&format!("connect {first}"), e))?;
        stream
            .set_read_timeout(Some(opts.timeout))
            .and_then(|()| stream.set_write_timeout(Some(opts.timeout)))
            .and_then(|()| stream.set_nodelay(true))
            .map_err(|e| io_err("configure socket", e))?;
        let reader = BufReader::new(
            stream
                .try_clone()
                .map_err(|e| io_err("configure socket", e))?,
        );
        let mut me = GpasciiTcp {
            reader,
            writer: std::io::BufWriter::new(stream),
            opts,
        };
        if !me.opts.banner.is_empty() {
            me.wait_for_banner()?;
        }
        Ok(me)
    }

    fn read_reply_line(&mut self, what: &str) -> Result<String, PmacError> {
        let mut line = String::new();
        let n = self
            .reader
            .read_line(&mut line)
            .map_err(|e| io_err(what, e))?;
        if n == 0 {
            return Err(PmacError::transport(format!(
                "{what}: the controller closed the connection"
            )));
        }
        Ok(line
            .chars()
            .filter(|c| !c.is_control())
            .collect::<String>()
            .trim()
            .to_string())
    }

    fn wait_for_banner(&mut self) -> Result<(), PmacError> {
        for _ in 0..self.opts.max_reply_lines {
            let line = self.read_reply_line("waiting for the banner")?;
            if line.contains(&self.opts.banner) {
                return Ok(());
            }
        }
        Err(PmacError::transport(format!(
            "no banner \"{}\" from the controller",
            self.opts.banner
        )))
    }
}

impl Transport for GpasciiTcp {
    fn send(&mut self, line: &str) -> Result<(), PmacError> {
        writeln!(self.writer, "{line}").map_err(|e| io_err("send", e))
    }
    fn capacity(&self) -> Option<usize> {
        Some(self.opts.capacity_lines)
    }
    fn lines_remaining(&mut self) -> Result<usize, PmacError> {
        let query = self.opts.query.clone();
        self.send(&query)?;
        self.flush()?;
        for _ in 0..self.opts.max_reply_lines {
            let line = self.read_reply_line("lines-remaining query")?;
            if line.to_ascii_lowercase().contains("error") {
                return Err(PmacError::controller(&line));
            }
            if let Ok(n) = line.parse::<usize>() {
                return Ok(n);
            }
            // echo of a sent line, prompt or blank line: skip
        }
        Err(PmacError::transport(format!(
            "no number in reply to `{query}`"
        )))
    }
    fn wait(&mut self) {
        std::thread::sleep(self.opts.poll_interval);
    }
    fn flush(&mut self) -> Result<(), PmacError> {
        self.writer.flush().map_err(|e| io_err("send", e))
    }
}

/// Request types and codes of the Turbo PMAC Ethernet protocol (ETHERNETCMD, 8-byte header).
pub mod turbo_eth {
    /// Host to controller.
    pub const VR_DOWNLOAD: u8 = 0x40;
    /// Controller to host.
    pub const VR_UPLOAD: u8 = 0xC0;
    /// Send a command line and get its response.
    pub const VR_PMAC_GETRESPONSE: u8 = 0xBF;
    /// Flush the controller's response queue (answered by one byte).
    pub const VR_PMAC_FLUSH: u8 = 0xB3;
    /// Largest data part of one packet.
    pub const MAX_DATA: usize = 1492;
    /// ACK ends a normal response.
    pub const ACK: u8 = 0x06;
    /// BELL starts an error response `<BELL>ERRnnn<CR>`.
    pub const BELL: u8 = 0x07;
    /// STX starts a `<STX>data<CR>` response.
    pub const STX: u8 = 0x02;

    /// The 8-byte header followed by `data`; 16-bit fields in network byte order (as `htons` in host code).
    pub fn packet(request_type: u8, request: u8, data: &[u8]) -> Vec<u8> {
        let mut p = Vec::with_capacity(8 + data.len());
        p.push(request_type);
        p.push(request);
        p.extend_from_slice(&0u16.to_be_bytes()); // wValue
        p.extend_from_slice(&0u16.to_be_bytes()); // wIndex
        p.extend_from_slice(&(data.len() as u16).to_be_bytes()); // wLength
        p.extend_from_slice(data);
        p
    }
}

/// Settings of the Turbo PMAC Ethernet transport.
#[derive(Debug, Clone, PartialEq)]
pub struct TurboEthernetOptions {
    /// Rotary buffer capacity in lines.
    pub capacity_lines: usize,
    /// Read timeout for each response.
    pub timeout: Duration,
    /// Pause between polls of a full buffer.
    pub poll_interval: Duration,
    /// Longest response accepted, in bytes.
    pub max_response: usize,
}

impl Default for TurboEthernetOptions {
    fn default() -> Self {
        TurboEthernetOptions {
            capacity_lines: 256,
            timeout: Duration::from_secs(5),
            poll_interval: Duration::from_millis(20),
            max_response: 64 * 1024,
        }
    }
}

/// A Turbo PMAC over Ethernet (TCP port 1025): every line is sent as a `VR_PMAC_GETRESPONSE` packet and its
/// response is read at once (`data<CR>...<ACK>` normally, `<BELL>ERRnnn<CR>` on error, which is reported as
/// E7004), so an error stops the stream at the offending line. Needs I3=2 and I6=1 (ACK handshake, errors
/// reported) on the controller.
pub struct TurboEthernet {
    stream: TcpStream,
    opts: TurboEthernetOptions,
}

impl TurboEthernet {
    /// Connects and flushes the controller's response queue.
    pub fn connect(
        addr: impl ToSocketAddrs,
        opts: TurboEthernetOptions,
    ) -> Result<Self, PmacError> {
        let first = addr
            .to_socket_addrs()
            .map_err(|e| io_err("resolve address", e))?
            .next()
            .ok_or_else(|| PmacError::transport("no address to connect to"))?;
        let stream = TcpStream::connect_timeout(&first, opts.timeout)
            .map_err(|e| io_err(&format!("connect {first}"), e))?;
        stream
            .set_read_timeout(Some(opts.timeout))
            .and_then(|()| stream.set_write_timeout(Some(opts.timeout)))
            .and_then(|()| stream.set_nodelay(true))
            .map_err(|e| io_err("configure socket", e))?;
        let mut me = TurboEthernet { stream, opts };
        me.write_packet(turbo_eth::VR_DOWNLOAD, turbo_eth::VR_PMAC_FLUSH, &[])?;
        let mut ack = [0u8; 1];
        std::io::Read::read_exact(&mut me.stream, &mut ack).map_err(|e| io_err("flush", e))?;
        Ok(me)
    }

    fn write_packet(&mut self, rt: u8, req: u8, data: &[u8]) -> Result<(), PmacError> {
        self.stream
            .write_all(&turbo_eth::packet(rt, req, data))
            .map_err(|e| io_err("send", e))
    }

    /// Sends one command line and returns its response text (lines joined by `\n`, without ACK).
    pub fn request(&mut self, line: &str) -> Result<String, PmacError> {
        let mut data = line.as_bytes().to_vec();
        data.push(b'\r');
        if data.len() > turbo_eth::MAX_DATA {
            return Err(PmacError::transport(format!(
                "line of {} bytes is longer than a packet ({} bytes)",
                data.len(),
                turbo_eth::MAX_DATA
            )));
        }
        self.write_packet(
            turbo_eth::VR_DOWNLOAD,
            turbo_eth::VR_PMAC_GETRESPONSE,
            &data,
        )?;
        let mut resp: Vec<u8> = Vec::new();
        let mut byte = [0u8; 1];
        let mut flagged = false;
        loop {
            std::io::Read::read_exact(&mut self.stream, &mut byte)
                .map_err(|e| io_err(&format!("response to `{line}`"), e))?;
            match byte[0] {
                turbo_eth::ACK => break,
                turbo_eth::BELL | turbo_eth::STX if resp.is_empty() => flagged = true,
                b'\r' if flagged => break,
                b => resp.push(b),
            }
            if resp.len() > self.opts.max_response {
                return Err(PmacError::transport(format!(
                    "response to `{line}` is longer than {} bytes",
                    self.opts.max_response
                )));
            }
        }
        let text = String::from_utf8_lossy(&resp)
            .split('\r')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join("\n");
        if (flagged && text.to_ascii_uppercase().starts_with("ERR"))
            || text.to_ascii_lowercase().contains("error")
        {
            return Err(PmacError::controller(&format!("{text} (after `{line}`)")));
        }
        Ok(text)
    }
}

impl Transport for TurboEthernet {
    fn send(&mut self, line: &str) -> Result<(), PmacError> {
        self.request(line).map(|_| ())
    }
    fn capacity(&self) -> Option<usize> {
        Some(self.opts.capacity_lines)
    }
    fn lines_remaining(&mut self) -> Result<usize, PmacError> {
        let text = self.request("PR")?;
        text.lines()
            .rev()
            .find_map(|l| l.trim().parse::<usize>().ok())
            .ok_or_else(|| PmacError::transport(format!("no number in reply to `PR`: {text:?}")))
    }
    fn wait(&mut self) {
        std::thread::sleep(self.opts.poll_interval);
    }
    fn flush(&mut self) -> Result<(), PmacError> {
        Ok(())
    }
}
