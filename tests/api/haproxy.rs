//! Debian's `haproxy` with the deployment example's `deploy/haproxy.cfg`, its
//! servers' addresses and its error file's path made a test's own, and a
//! stats page to tell which replicas it has up. Used by the balancer test and
//! by the soak bench (which includes this file); `haproxy -c` checks the file
//! first.

use crate::wire::{free_port, http};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

pub struct Balancer {
    child: Child,
    pub port: u16,
    stats: u16,
    _dir: tempfile::TempDir,
}

impl Balancer {
    /// HAProxy with the deployment's configuration in front of `replicas`
    /// (one to three: each its service's port and its operator's, where
    /// the balancer checks /readyz).
    pub fn start(replicas: &[(u16, u16)]) -> Self {
        let root = env!("CARGO_MANIFEST_DIR");
        let cfg = std::fs::read_to_string(format!("{root}/deploy/haproxy.cfg")).unwrap();
        let (port, stats, dir) = (free_port(), free_port(), tempfile::tempdir().unwrap());
        let mut text = cfg
            .replace("bind :8080", &format!("bind 127.0.0.1:{port}"))
            .replace("/usr/local/etc/haproxy/errors", &format!("{root}/deploy/errors"))
            .replace("log stdout format raw local0 info", "");
        for (k, (p, operator)) in replicas.iter().enumerate() {
            let (example, ours) =
                (format!("mechdyn-{}:8080 port 9464", k + 1), format!("127.0.0.1:{p} port {operator}"));
            assert!(text.contains(&example), "the example's server line: {example}");
            text = text.replace(&example, &ours);
        }
        // Fewer replicas than the example's three: the others' lines go.
        let unused = |l: &&str| l.split_whitespace().nth(2).is_some_and(|a| a.starts_with("mechdyn-"));
        text = text.lines().filter(|l| !unused(l)).collect::<Vec<_>>().join("\n");
        text.push_str(&format!(
            "\nfrontend stats\n    bind 127.0.0.1:{stats}\n    stats enable\n    stats uri /stats\n"
        ));
        let file = dir.path().join("haproxy.cfg");
        std::fs::write(&file, text).unwrap();
        let check = Command::new("haproxy").arg("-c").arg("-f").arg(&file).output().unwrap();
        assert!(check.status.success(), "{}", String::from_utf8_lossy(&check.stderr));
        let child =
            Command::new("haproxy").arg("-db").arg("-f").arg(&file).stdout(Stdio::null()).stderr(Stdio::null()).spawn();
        let b = Self { child: child.unwrap(), port, stats, _dir: dir };
        b.wait_until(|up| up == replicas.len(), "every replica up");
        b
    }

    /// How many of the replicas HAProxy has up.
    pub fn up(&self) -> usize {
        let Ok((200, csv)) = http(self.stats, "GET", "/stats;csv", "") else { return 0 };
        csv.lines().filter(|l| l.starts_with("replicas,mechdyn-") && l.split(',').nth(17) == Some("UP")).count()
    }

    /// Waits (30 s at most) until `ok(up)`; the time it took.
    pub fn wait_until(&self, ok: impl Fn(usize) -> bool, what: &str) -> Duration {
        let started = Instant::now();
        while !ok(self.up()) {
            assert!(started.elapsed() < Duration::from_secs(30), "{what}: not in 30 s ({} up)", self.up());
            std::thread::sleep(Duration::from_millis(50));
        }
        started.elapsed()
    }
}

impl Drop for Balancer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
