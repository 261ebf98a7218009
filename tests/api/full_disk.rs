//! The full-disk cycle an operator meets, on a real small filesystem
//! ([`SmallDisk`]): the disk fills, jobs are deleted and deferred on it,
//! space returns, jobs are written, the service is killed (SIGKILL) and
//! started again on the same files. A 201, a 202 and a 204 each mean
//! committed: every job acknowledged is there after the restart, with its
//! result, and every job whose DELETE was answered 204 is gone. While
//! writes cannot commit `/readyz` says so.

use crate::crash::{free_port, http, http_with};
use crate::helpers::request;
use crate::small_disk::SmallDisk;
use serde_json::Value;

/// One exchange; a connection that failed counts as status 0.
fn call(port: u16, method: &str, path: &str, body: &str) -> (u16, String) {
    http(port, method, path, body).unwrap_or((0, String::new()))
}

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("not JSON ({e}): {text}"))
}

#[test]
fn deletes_and_writes_around_a_full_disk_survive_a_kill() {
    let Some(disk) = SmallDisk::new(3 << 10, 1024) else {
        eprintln!("skipped: this machine does not allow a tmpfs in a mount namespace (needs root)");
        return;
    };
    let port = free_port();
    let child = disk.start(port, &[]);
    let mut body = request("p113_pulley");
    body["samples"] = 300.into();
    let body = body.to_string();

    // The disk fills.
    let (mut stored, full) = crate::small_disk::fill(port, &body);
    assert_eq!(full.0, 507, "{}", full.1);
    assert!(stored.len() > 12, "too few jobs stored to delete ten: {}", stored.len());
    let (status, text) = call(port, "GET", "/readyz", "");
    assert_eq!(status, 503, "ready while jobs cannot be stored: {text}");
    assert!(json(&text)["reason"].as_str().unwrap().contains("full"), "{text}");

    // Deletes on the full disk: each done (204) or refused as full (507), nothing else.
    let mut deleted = Vec::new();
    for (id, result) in stored.drain(..10).collect::<Vec<_>>() {
        let (status, text) = call(port, "DELETE", &format!("/v1/jobs/{id}"), "");
        match status {
            204 => deleted.push(id),
            507 => {
                assert!(json(&text)["detail"].as_str().unwrap().contains("not deleted"), "{text}");
                stored.push((id, result));
            }
            _ => panic!("a DELETE on a full disk answered {status}: {text}"),
        }
    }
    // A deferred job on the full disk: 202 only once it is stored, else 507.
    let prefer = "Prefer: respond-async\r\n";
    let mut deferred = Vec::new();
    let (status, text) = http_with(port, "POST", "/v1/flywheel", prefer, &body).unwrap();
    match status {
        202 => deferred.push(json(&text)["id"].as_str().unwrap().to_string()),
        507 => {}
        _ => panic!("a deferred POST on a full disk answered {status}: {text}"),
    }

    // Space returns: ready again, and every write is acknowledged.
    disk.free();
    let (status, text) = call(port, "GET", "/readyz", "");
    assert_eq!(status, 200, "not ready once space returned: {text}");
    for _ in 0..3 {
        let (status, text) = call(port, "POST", "/v1/flywheel", &body);
        assert_eq!(status, 201, "{text}");
        let job = json(&text);
        stored.push((job["id"].as_str().unwrap().to_string(), job["result"].clone()));
    }
    let (id, _) = stored.remove(0);
    let (status, text) = call(port, "DELETE", &format!("/v1/jobs/{id}"), "");
    assert_eq!(status, 204, "{text}");
    deleted.push(id);
    let (status, text) = http_with(port, "POST", "/v1/flywheel", prefer, &body).unwrap();
    assert_eq!(status, 202, "{text}");
    deferred.push(json(&text)["id"].as_str().unwrap().to_string());

    // Killed, started again on the same files.
    drop(child);
    let port = free_port();
    let _child = disk.start(port, &[]);
    for (id, result) in &stored {
        let (status, text) = call(port, "GET", &format!("/v1/jobs/{id}"), "");
        assert_eq!(status, 200, "acknowledged job {id} lost: {text}");
        assert_eq!(&json(&text)["result"], result, "job {id} changed");
    }
    for id in &deferred {
        let (status, text) = call(port, "GET", &format!("/v1/jobs/{id}"), "");
        assert_eq!(status, 200, "deferred job {id}, answered 202, lost: {text}");
    }
    for id in &deleted {
        let (status, text) = call(port, "GET", &format!("/v1/jobs/{id}"), "");
        assert_eq!(status, 404, "job {id}, deleted with a 204, is back: {text}");
    }
    eprintln!(
        "{} jobs kept and {} deleted (204) around a full disk, {} deferred; all as acknowledged after a SIGKILL",
        stored.len(),
        deleted.len(),
        deferred.len()
    );
}
