//! The flood: the largest jobs the limits allow, from many connections at
//! once, to show that memory stays bounded and that every answer is a 201 or
//! a 503 with Retry-After. The largest jobs are found by asking the service:
//! each kind is POSTed at its largest count (100000 steps or samples), and
//! the count its 422 says would fit is used (or the largest, if it fits).

use crate::http::Service;
use serde_json::Value;
use std::fmt::Write as _;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::process::Command;
use std::time::{Duration, Instant};

/// A request of the flood: method, path and body.
pub type Request = (&'static str, String, Option<Value>);

/// One request on a fresh connection: (status, body).
fn exchange(addr: &str, method: &str, path: &str, body: &str) -> (u16, String) {
    let Ok(mut s) = TcpStream::connect(addr) else { return (0, String::new()) };
    let head = format!(
        "{method} {path} HTTP/1.1\r\nHost: localhost\r\nContent-Type: application/json\r\nContent-Length: {}\r\n\
         Connection: close\r\n\r\n",
        body.len()
    );
    let mut raw = Vec::new();
    if s.write_all(head.as_bytes())
        .and_then(|()| s.write_all(body.as_bytes()))
        .and_then(|()| s.read_to_end(&mut raw))
        .is_err()
    {
        return (0, String::new());
    }
    let text = String::from_utf8_lossy(&raw);
    let status = text.get(9..12).and_then(|c| c.parse().ok()).unwrap_or(0);
    (status, text.split_once("\r\n\r\n").map_or(String::new(), |(_, b)| b.to_string()))
}

/// Sets the member at `pointer` (its parent object exists).
fn set(body: &mut Value, pointer: &str, value: u64) {
    let (parent, key) = pointer.rsplit_once('/').expect("a pointer");
    body.pointer_mut(parent).and_then(Value::as_object_mut).expect("its parent").insert(key.into(), value.into());
}

/// `body` with the count at `pointer` set to the largest the service accepts.
fn largest(addr: &str, path: &str, mut body: Value, pointer: &str) -> (Value, String) {
    set(&mut body, pointer, 100_000);
    let (status, text) = exchange(addr, "POST", path, &body.to_string());
    if status == 422 {
        let problem: Value = serde_json::from_str(&text).unwrap_or_default();
        let message = problem["errors"][0]["message"].as_str().unwrap_or_default().to_string();
        let name = pointer.rsplit('/').next().unwrap_or_default();
        let fit = message
            .split(&format!("{name} ≤ "))
            .nth(1)
            .and_then(|m| m.split(|c: char| !c.is_ascii_digit()).next()?.parse::<u64>().ok())
            .unwrap_or(1000);
        set(&mut body, pointer, fit);
    }
    let (status, text) = exchange(addr, "POST", path, &body.to_string());
    let size = serde_json::from_str::<Value>(&text).map_or(0, |job| job["result"].to_string().len());
    let count = body.pointer(pointer).cloned().unwrap_or_default();
    (body, format!("`{path}` with `{pointer}` = {count}: {status}, result {:.1} MB", size as f64 / 1e6))
}

/// The wrk script: the requests in turn, answers counted by status, 503s without Retry-After counted.
fn lua(requests: &[Request]) -> String {
    let mut s = String::from("local reqs = {\n");
    for (method, path, body) in requests {
        let body = body.as_ref().map_or("nil".into(), |b| format!("[==[{b}]==]"));
        let _ = writeln!(s, "  {{\"{method}\", \"{path}\", {body}}},");
    }
    s + r#"}
local n = 0
local threads = {}
function setup(thread) table.insert(threads, thread) end
function init(args) counts = {}; missing = 0 end
request = function()
  n = n + 1
  local r = reqs[(n % #reqs) + 1]
  if r[3] then return wrk.format(r[1], r[2], {["Content-Type"] = "application/json"}, r[3]) end
  return wrk.format(r[1], r[2])
end
function response(status, headers, body)
  counts[status] = (counts[status] or 0) + 1
  if status == 503 and headers["retry-after"] == nil and headers["Retry-After"] == nil then missing = missing + 1 end
end
function done(summary, latency, requests)
  local total = {}
  local lost = 0
  for _, t in ipairs(threads) do
    for k, v in pairs(t:get("counts")) do total[k] = (total[k] or 0) + v end
    lost = lost + t:get("missing")
  end
  for k, v in pairs(total) do io.write(string.format("status %d %d\n", k, v)) end
  io.write(string.format("retry_after_missing %d\n", lost))
end
"#
}

/// One flood: `connections` for `seconds`; the report's section.
pub fn run(service: &Service, requests: &[Request], connections: u32, seconds: u64) -> String {
    let script = tempfile::NamedTempFile::new().expect("temp file");
    std::fs::write(script.path(), lua(requests)).expect("write the wrk script");
    let (before, _) = service.memory();
    let mut wrk = Command::new("wrk")
        .args(["-t", "2", "-c", &connections.to_string(), "-d", &format!("{seconds}s"), "--timeout", "60s", "-s"])
        .arg(script.path())
        .arg(format!("http://{}/", service.addr))
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("wrk");
    let start = Instant::now();
    let mut samples = Vec::new();
    while wrk.try_wait().expect("wrk").is_none() {
        std::thread::sleep(Duration::from_secs(1));
        samples.push((start.elapsed().as_secs(), service.memory().0));
    }
    let out = String::from_utf8_lossy(&wrk.wait_with_output().expect("wrk output").stdout).into_owned();
    let (_, peak) = service.memory();
    let statuses: Vec<String> =
        out.lines().filter_map(|l| l.strip_prefix("status ")).map(|l| l.replacen(' ', ": ", 1)).collect();
    let missing = out.lines().find_map(|l| l.strip_prefix("retry_after_missing ")).unwrap_or("?");
    let socket =
        out.lines().find_map(|l| l.trim().strip_prefix("Socket errors:")).unwrap_or(" none").trim().to_string();
    let rate = out.lines().find_map(|l| l.strip_prefix("Requests/sec:")).unwrap_or("?").trim().to_string();
    let most = samples.iter().map(|s| s.1).fold(0.0, f64::max);
    let series: Vec<String> = samples.iter().step_by(5).map(|(t, m)| format!("{t} s: {m:.0}")).collect();
    format!(
        "### {connections} connections, {seconds} s\n\n| measure | value |\n|---|---|\n\
         | answers by status | {} |\n| 503 answers without Retry-After | {missing} |\n| socket errors | {socket} |\n\
         | requests per second | {rate} |\n| resident memory before | {before:.1} MiB |\n\
         | largest sample (every 1 s) | {most:.1} MiB |\n| peak (VmHWM, since start) | {peak:.1} MiB |\n\n\
         Resident memory (MiB) every 5 s: {}\n\n",
        statuses.join(", "),
        series.join(", ")
    )
}

/// The largest jobs of each kind the limits allow, and the reads of large results.
pub fn requests(addr: &str, fixture: impl Fn(&str) -> Value) -> (Vec<Request>, String) {
    let (k1, k1_said) =
        largest(addr, "/v1/kinetostatics", fixture("requests/k1_offset_slider_crank.json"), "/input/steps");
    let (fly, fly_said) = largest(addr, "/v1/flywheel", fixture("requests/p103_slider.json"), "/samples");
    let (dyn_, dyn_said) = largest(addr, "/v1/dynamics", fixture("requests/d1_scotch_yoke_machine.json"), "/samples");
    let (_, text) = exchange(addr, "POST", "/v1/kinetostatics", &k1.to_string());
    let id = serde_json::from_str::<Value>(&text).map_or(String::new(), |j| j["id"].as_str().unwrap_or("").to_string());
    let list = vec![
        ("POST", "/v1/kinetostatics".to_string(), Some(k1)),
        ("POST", "/v1/flywheel".to_string(), Some(fly)),
        ("POST", "/v1/dynamics".to_string(), Some(dyn_)),
        ("GET", format!("/v1/jobs/{id}"), None),
        ("GET", format!("/v1/jobs/{id}/result.csv"), None),
        ("GET", "/v1/jobs?limit=100".to_string(), None),
    ];
    let said = format!(
        "The largest jobs, as the service sized them:\n\n- {k1_said}\n- {fly_said}\n- {dyn_said}\n\nplus reads of a \
         stored K1 job of that size (`GET /v1/jobs/{{id}}`, its CSV) and the largest page of the jobs list \
         (`GET /v1/jobs?limit=100`).\n\n"
    );
    (list, said)
}
