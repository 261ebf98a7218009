//! A real, small filesystem for the tests of a full disk: a tmpfs of a few
//! MiB in a mount namespace of its own (root only), part of it taken by a
//! ballast file that the test removes to give space back. A holder process
//! keeps the namespace alive, so the service can be killed and started
//! again on the same files.

use serde_json::Value;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// Whether this machine lets the test make a mount namespace with a tmpfs.
pub fn can_mount() -> bool {
    Command::new("unshare")
        .args(["-m", "sh", "-c", "mount -t tmpfs -o size=1m tmpfs /mnt"])
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

pub struct SmallDisk {
    /// The process holding the namespace (a `sleep` in it).
    holder: Child,
    /// The mount point: a folder of the host, a tmpfs inside the namespace.
    pub dir: String,
    _folder: tempfile::TempDir,
}

impl SmallDisk {
    /// A tmpfs of `size_kib` holding `ballast_kib` of ballast, or None where
    /// this machine does not allow one (not root).
    pub fn new(size_kib: usize, ballast_kib: usize) -> Option<Self> {
        if !can_mount() {
            return None;
        }
        let folder = tempfile::tempdir().unwrap();
        let dir = folder.path().display().to_string();
        let script = format!(
            "mount -t tmpfs -o size={size_kib}k tmpfs {dir} && dd if=/dev/zero of={dir}/ballast bs=1k \
             count={ballast_kib} 2>/dev/null && touch {dir}/ready && exec sleep 100000"
        );
        let holder = Command::new("unshare").args(["-m", "sh", "-c", &script]).stderr(Stdio::null()).spawn().unwrap();
        let disk = Self { holder, dir, _folder: folder };
        let started = Instant::now();
        while !disk.run(&format!("test -f {}/ready", disk.dir)) {
            assert!(started.elapsed() < Duration::from_secs(10), "the tmpfs was not mounted");
            std::thread::sleep(Duration::from_millis(10));
        }
        Some(disk)
    }

    /// A `sh -c` command run inside the namespace: whether it succeeded.
    pub fn run(&self, command: &str) -> bool {
        let pid = self.holder.id().to_string();
        let status =
            Command::new("nsenter").args(["-t", &pid, "-m", "sh", "-c", command]).stderr(Stdio::null()).status();
        status.is_ok_and(|s| s.success())
    }

    /// Gives the ballast's space back.
    pub fn free(&self) {
        assert!(self.run(&format!("rm {}/ballast", self.dir)), "the ballast could not be removed");
    }

    /// The service on this disk (its database `jobs.db` there), listening
    /// on `port`, with more environment variables; waits for /healthz.
    pub fn start(&self, port: u16, env: &[(&str, &str)]) -> Running {
        let pid = self.holder.id().to_string();
        let child = Command::new("nsenter")
            .args(["-t", &pid, "-m", env!("CARGO_BIN_EXE_mechdyn")])
            .env("DATABASE_URL", format!("sqlite://{}/jobs.db", self.dir))
            .env("MECHDYN_ADDR", format!("127.0.0.1:{port}"))
            .env("RUST_LOG", "warn")
            .envs(env.iter().copied())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let started = Instant::now();
        while !matches!(crate::crash::http(port, "GET", "/healthz", ""), Ok((200, _))) {
            assert!(started.elapsed() < Duration::from_secs(30), "the service did not start");
            std::thread::sleep(Duration::from_millis(20));
        }
        Running(child)
    }
}

/// POSTs `body` to `/v1/flywheel` at `port` until an answer is not a 201:
/// the jobs stored (id and result), and that answer (status and body).
pub fn fill(port: u16, body: &str) -> (Vec<(String, Value)>, (u16, String)) {
    let mut stored = Vec::new();
    loop {
        let (status, text) = crate::crash::http(port, "POST", "/v1/flywheel", body).unwrap_or((0, String::new()));
        if status != 201 {
            return (stored, (status, text));
        }
        let job: Value = serde_json::from_str(&text).unwrap();
        stored.push((job["id"].as_str().unwrap().to_string(), job["result"].clone()));
        assert!(stored.len() < 1000, "the small disk never filled up");
    }
}

/// The service started on a small disk, killed (SIGKILL) when dropped, so
/// that a test failing half-way leaves no process behind.
pub struct Running(Child);

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

impl Drop for SmallDisk {
    fn drop(&mut self) {
        let _ = self.holder.kill();
        let _ = self.holder.wait();
    }
}
