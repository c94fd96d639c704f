//! Issue 28 item 5, "a folder that cannot be read fails only the compounds inside it", checked for
//! real: a compound folder with mode 000 beside a readable one, the run made as an unprivileged user
//! (`setpriv` to nobody), since root reads every folder whatever its mode. Skipped, with a message,
//! where that cannot be done (not root, no `setpriv`, or the binary not reachable by nobody).

use crate::support::{bin, data_dir, temp_dir};
use std::os::unix::fs::PermissionsExt;
use std::process::Command;

/// `setpriv` to nobody (uid/gid 65534), or why not.
fn as_nobody() -> Result<Command, String> {
    let root = Command::new("id")
        .arg("-u")
        .output()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim() == "0")
        .unwrap_or(false);
    if !root {
        return Err("not root: cannot run as another user".into());
    }
    let mut c = Command::new("setpriv");
    c.args(["--reuid=65534", "--regid=65534", "--clear-groups", bin()]);
    match c.arg("--version").output() {
        Ok(o) if o.status.success() => {}
        Ok(o) => {
            return Err(format!(
                "the binary does not run as nobody: {}",
                String::from_utf8_lossy(&o.stderr).trim()
            ))
        }
        Err(e) => return Err(format!("no setpriv: {e}")),
    }
    let mut c = Command::new("setpriv");
    c.args(["--reuid=65534", "--regid=65534", "--clear-groups", bin()]);
    Ok(c)
}

#[test]
fn an_unreadable_compound_folder_fails_only_its_compound() {
    let mut run = match as_nobody() {
        Ok(c) => c,
        Err(why) => {
            eprintln!("skipped: {why}");
            return;
        }
    };
    let dir = temp_dir("unreadable-folder");
    let export = data_dir().join("pyvisco-ems-ca/freq_Eplexor_raw.xls");
    for name in ["good", "locked"] {
        std::fs::create_dir(dir.join(name)).unwrap();
        std::fs::copy(&export, dir.join(name).join("ems-ca.xls")).unwrap();
    }
    std::fs::write(
        dir.join("scenes.toml"),
        "[[scene]]\nname = \"s\"\nroll_radius_mm = 66.5\nload_n_per_m = 10000.0\nspeed_m_s = 4.0\ntemps_c = [0.0, 20.0]\n",
    )
    .unwrap();
    let out = dir.join("out");
    std::fs::create_dir(&out).unwrap();
    let mode = |p: &std::path::Path, m: u32| {
        std::fs::set_permissions(p, std::fs::Permissions::from_mode(m)).unwrap()
    };
    mode(&dir, 0o755);
    mode(&out, 0o777);
    mode(&dir.join("locked"), 0o000);
    let o = run
        .arg("run")
        .arg(&dir)
        .arg("--out")
        .arg(&out)
        .args(["--no-bands", "--json"])
        .output()
        .unwrap();
    mode(&dir.join("locked"), 0o755);
    let err = String::from_utf8_lossy(&o.stderr);
    // the run finishes: exit 1 says a compound failed, and only that one
    assert_eq!(o.status.code(), Some(1), "{err}");
    let summary: serde_json::Value = serde_json::from_slice(&o.stdout).expect("one JSON object");
    let compounds = summary["detail"]["compounds"]
        .as_array()
        .expect("compounds listed");
    let by_name = |n: &str| {
        compounds
            .iter()
            .find(|c| c["compound"] == n)
            .unwrap_or_else(|| panic!("{n} listed: {summary}"))
    };
    assert!(by_name("good")["error"].is_null(), "{summary}");
    let why = by_name("locked")["error"]
        .as_str()
        .unwrap_or_default()
        .to_string();
    assert!(why.contains("locked") && why.contains("ermission"), "{why}");
    assert!(out.join("reports/good/datasheet.html").is_file());
    let index = std::fs::read_to_string(out.join("reports/index.html")).unwrap();
    assert!(
        index.contains("locked"),
        "the index names the failed compound"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
