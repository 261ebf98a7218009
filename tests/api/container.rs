//! The image as an operator runs it, with podman: the Dockerfile's image
//! (built by `.ci/container`, named by MECHDYN_IMAGE) started with a
//! read-only root and a named volume for /data. It answers /healthz and the
//! README's first job with the README's value; its HEALTHCHECK passes under
//! `podman healthcheck run`; its process runs as uid 65532; nothing but the
//! volume is writable; a job stays byte for byte through a restart and into
//! a new container on the same volume; `podman stop` ends it gracefully
//! (exit 0, not the SIGKILL after the stop timeout).
//!
//! Without MECHDYN_IMAGE the test says it is skipped, unless
//! MECHDYN_REQUIRE_PODMAN is set (CI sets both).

use crate::crash::{free_port, http};
use crate::readme::readme_job;
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn podman(args: &[&str]) -> Output {
    let out = Command::new("podman").args(args).output().expect("podman runs");
    let said = String::from_utf8_lossy(&out.stderr);
    // podman without systemd says it cannot arm the healthcheck's timer; the check itself runs.
    let said: Vec<&str> = said.lines().filter(|l| !l.contains("/run/systemd/private")).collect();
    if !said.is_empty() {
        eprintln!("podman {}: {}", args.join(" "), said.join("\n"));
    }
    out
}

fn podman_ok(args: &[&str]) -> String {
    let out = podman(args);
    assert!(out.status.success(), "podman {} failed: {}", args.join(" "), String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout).unwrap().trim().to_string()
}

fn inspect(name: &str, format: &str) -> String {
    podman_ok(&["inspect", name, "--format", format])
}

/// One container of the image; removed (and its volume kept) when dropped.
struct Container {
    name: String,
    port: u16,
}

impl Container {
    fn run(image: &str, name: &str, volume: &str) -> Self {
        let port = free_port();
        let publish = format!("127.0.0.1:{port}:8080");
        let mount = format!("{volume}:/data");
        podman_ok(&["run", "-d", "--name", name, "--read-only", "-v", &mount, "-p", &publish, image]);
        let container = Container { name: name.to_string(), port };
        container.wait_ready();
        container
    }

    fn wait_ready(&self) {
        let deadline = Instant::now() + Duration::from_secs(60);
        loop {
            match http(self.port, "GET", "/healthz", "") {
                Ok((200, body)) => return assert!(body.contains("\"ok\""), "{body}"),
                _ if Instant::now() < deadline => std::thread::sleep(Duration::from_millis(200)),
                other => panic!("{} not healthy in 60 s: {other:?}\n{}", self.name, self.logs()),
            }
        }
    }

    fn logs(&self) -> String {
        let out = podman(&["logs", &self.name]);
        format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
    }

    fn get(&self, path: &str) -> String {
        let (status, body) = http(self.port, "GET", path, "").unwrap();
        assert_eq!(status, 200, "GET {path}: {body}");
        body
    }

    /// `podman stop`: SIGTERM, then SIGKILL after 10 s; a graceful stop exits 0.
    fn stop(&self) {
        podman_ok(&["stop", "--time", "10", &self.name]);
        assert_eq!(inspect(&self.name, "{{.State.ExitCode}}"), "0", "{}", self.logs());
    }

    fn exec(&self, args: &[&str]) -> Output {
        podman(&[&["exec", self.name.as_str()][..], args].concat())
    }
}

impl Drop for Container {
    fn drop(&mut self) {
        podman(&["rm", "-f", "-t", "0", &self.name]);
    }
}

#[test]
fn the_image_serves_read_only_as_nonroot_and_keeps_its_jobs_on_the_volume() {
    let Ok(image) = std::env::var("MECHDYN_IMAGE") else {
        assert!(std::env::var_os("MECHDYN_REQUIRE_PODMAN").is_none(), "MECHDYN_IMAGE is not set (.ci/container)");
        return eprintln!("skipped: no image (MECHDYN_IMAGE; .ci/container builds one with podman)");
    };
    let tag = format!("mechdyn-test-{}", std::process::id());
    let volume = tag.clone();
    podman_ok(&["volume", "create", &volume]);
    let first = Container::run(&image, &format!("{tag}-a"), &volume);

    // The Dockerfile's HEALTHCHECK (`mechdyn healthcheck`), run by podman.
    podman_ok(&["healthcheck", "run", &first.name]);
    assert_eq!(inspect(&first.name, "{{.State.Health.Status}}"), "healthy");

    // The process itself, seen from the host: uid and gid 65532 (real, effective, saved, fs).
    let pid = inspect(&first.name, "{{.State.Pid}}");
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap();
    for field in ["Uid:", "Gid:"] {
        let ids: Vec<&str> =
            status.lines().find(|l| l.starts_with(field)).unwrap().split_whitespace().skip(1).collect();
        assert_eq!(ids, ["65532"; 4], "{field} of the container's process");
    }

    // Read-only root: mounted so (the process's own mount table), and the home the image gives
    // uid 65532 cannot be written; the volume can.
    assert_eq!(inspect(&first.name, "{{.HostConfig.ReadonlyRootfs}}"), "true");
    let mounts = std::fs::read_to_string(format!("/proc/{pid}/mountinfo")).unwrap();
    let options = |at: &str| {
        let line = mounts.lines().find(|l| l.split(' ').nth(4) == Some(at)).unwrap_or_else(|| panic!("{at}: {mounts}"));
        line.split(' ').nth(5).unwrap().split(',').next().unwrap().to_string()
    };
    assert_eq!((options("/").as_str(), options("/data").as_str()), ("ro", "rw"), "{mounts}");
    let refused = first.exec(&["/app/mechdyn", "backup", "/home/nonroot/copy.db"]);
    assert!(!refused.status.success(), "a write outside /data: {refused:?}");
    let backup = first.exec(&["/app/mechdyn", "backup", "/data/copy.db"]);
    assert!(backup.status.success(), "{backup:?}");

    // The README's job, with the README's value (checked against case F1's closed form in readme.rs).
    let (body, reads) = readme_job();
    let value = &reads.iter().find(|(p, _)| p.ends_with("/inertia_exact")).unwrap().1;
    let (status, created) = http(first.port, "POST", "/v1/flywheel", &body).unwrap();
    assert_eq!(status, 201, "{created}");
    let id = serde_json::from_str::<serde_json::Value>(&created).unwrap()["id"].as_str().unwrap().to_string();
    assert_eq!(&first.get(&format!("/v1/jobs/{id}/result/inertia_exact")), value);
    let stored = first.get(&format!("/v1/jobs/{id}"));

    // A restart of the same container, then a new container on the same volume.
    first.stop();
    podman_ok(&["start", &first.name]);
    first.wait_ready();
    assert_eq!(first.get(&format!("/v1/jobs/{id}")), stored, "after a restart");
    first.stop();
    drop(first);
    let second = Container::run(&image, &format!("{tag}-b"), &volume);
    assert_eq!(second.get(&format!("/v1/jobs/{id}")), stored, "in a new container");
    second.stop();
    drop(second);
    podman(&["volume", "rm", "-f", &volume]);
}
