//! A real PostgreSQL server of a test's own: Debian's `postgresql` package
//! (`.ci/run` installs it), a cluster made by `initdb` in a temporary
//! folder, listening on a free port of 127.0.0.1, trusted for the user
//! `mechdyn`, stopped and removed when the test ends. As root, the server
//! runs as the `postgres` user (PostgreSQL refuses to run as root).
//!
//! Without the package a test says it is skipped, unless
//! MECHDYN_REQUIRE_POSTGRES is set (CI sets it).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

pub struct PgServer {
    bin: PathBuf,
    data: PathBuf,
    pub port: u16,
    /// Run the server's programs as `postgres` (the tests run as root).
    as_postgres: bool,
    _dir: tempfile::TempDir,
}

impl PgServer {
    /// A new server, started; None (and "skipped" said) where PostgreSQL is
    /// not installed and not required.
    pub fn start(test: &str) -> Option<Self> {
        let Some(bin) = bindir() else {
            assert!(std::env::var_os("MECHDYN_REQUIRE_POSTGRES").is_none(), "PostgreSQL (initdb, pg_ctl) is required");
            eprintln!("skipped {test}: PostgreSQL (Debian's postgresql package) is not installed");
            return None;
        };
        let dir = tempfile::tempdir().unwrap();
        let as_postgres = is_root();
        if as_postgres {
            chown_to_postgres(dir.path());
        }
        let data = dir.path().join("data");
        let server = Self { bin, data, port: crate::wire::free_port(), as_postgres, _dir: dir };
        let data = server.data.display().to_string();
        server.run("initdb", &["-D", &data, "-U", "mechdyn", "--auth=trust", "-E", "UTF8", "--no-sync"]);
        server.start_again();
        Some(server)
    }

    /// The URL of database `db` (`postgres` exists from the start).
    pub fn url(&self, db: &str) -> String {
        format!("postgres://mechdyn:unused-s3cret@127.0.0.1:{}/{db}", self.port)
    }

    /// A new empty database: its URL.
    pub async fn database(&self) -> String {
        let name = format!("t{}", uuid::Uuid::new_v4().simple());
        let admin = sqlx::PgPool::connect(&self.url("postgres")).await.unwrap();
        sqlx::query(sqlx::AssertSqlSafe(format!("CREATE DATABASE {name}"))).execute(&admin).await.unwrap();
        admin.close().await;
        self.url(&name)
    }

    /// Stops the server at once (its clients see their connections refused).
    pub fn stop(&self) {
        self.run("pg_ctl", &["-D", &self.data.display().to_string(), "-m", "immediate", "-w", "stop"]);
    }

    /// Starts the (stopped) server again on the same port and data.
    pub fn start_again(&self) {
        let options = format!(
            "-c listen_addresses=127.0.0.1 -c port={} -c unix_socket_directories={} -c fsync=off",
            self.port,
            self.data.display()
        );
        let log = self.data.join("server.log").display().to_string();
        self.run("pg_ctl", &["-D", &self.data.display().to_string(), "-l", &log, "-o", &options, "-w", "start"]);
    }

    /// A client program of the same version (`pg_dump`, `pg_restore`), run
    /// as the test's user: it connects by TCP like any client.
    pub fn client(&self, program: &str) -> Command {
        Command::new(self.bin.join(program))
    }

    /// One of the server's programs, to run as `postgres` where needed.
    fn command(&self, program: &str) -> Command {
        let path = self.bin.join(program);
        if self.as_postgres {
            let mut c = Command::new("runuser");
            c.args(["-u", "postgres", "--"]).arg(path);
            c
        } else {
            Command::new(path)
        }
    }

    /// Runs one of the server's programs; it must succeed.
    fn run(&self, program: &str, args: &[&str]) {
        let out = self.command(program).args(args).stdin(Stdio::null()).output().unwrap();
        assert!(
            out.status.success(),
            "{program} {args:?}: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

impl Drop for PgServer {
    fn drop(&mut self) {
        let data = self.data.display().to_string();
        let mut stop = self.command("pg_ctl");
        let _ =
            stop.args(["-D", &data, "-m", "immediate", "stop"]).stdout(Stdio::null()).stderr(Stdio::null()).status();
    }
}

/// The folder of `initdb` and `pg_ctl` (Debian keeps them off PATH, under
/// /usr/lib/postgresql/VERSION/bin; the newest version wins).
fn bindir() -> Option<PathBuf> {
    let mut found: Vec<PathBuf> = std::fs::read_dir("/usr/lib/postgresql")
        .ok()?
        .filter_map(|e| Some(e.ok()?.path().join("bin")))
        .filter(|bin| bin.join("initdb").is_file() && bin.join("pg_ctl").is_file())
        .collect();
    found.sort_by_key(|p| p.parent().and_then(|v| v.file_name()?.to_str()?.parse::<u32>().ok()));
    found.pop()
}

fn is_root() -> bool {
    Command::new("id").arg("-u").output().is_ok_and(|o| o.stdout.trim_ascii() == b"0")
}

fn chown_to_postgres(dir: &Path) {
    let out = Command::new("chown").arg("postgres:postgres").arg(dir).output().unwrap();
    assert!(out.status.success(), "chown postgres {}: {}", dir.display(), String::from_utf8_lossy(&out.stderr));
}
