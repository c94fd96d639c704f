//! Seeds of the randomized tests (issue 19, item 4): random inputs that move from run to run.
//!
//! `VISCOROLL_SEED=N` (decimal or `0x` hex) replays a run; without it every run of the test binary
//! draws one fresh base seed (clock and process id). Each test mixes the base seed with its own name,
//! so tests do not share their streams, and prints `VISCOROLL_SEED=…` at its start: libtest shows a
//! failing test's output, so every failure names the seed that reproduces it, e.g.
//! `VISCOROLL_SEED=0x1234abcd cargo test --lib contact_props`.

use std::sync::OnceLock;

/// SplitMix64's output function (Steele, Lea & Flood 2014): a bijective 64-bit mixer.
fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The run's base seed: `VISCOROLL_SEED`, or a fresh one.
pub fn base_seed() -> u64 {
    static BASE: OnceLock<u64> = OnceLock::new();
    *BASE.get_or_init(|| match std::env::var("VISCOROLL_SEED") {
        Ok(text) => {
            let t = text.trim();
            let parsed = match t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
                Some(hex) => u64::from_str_radix(hex, 16),
                None => t.parse::<u64>(),
            };
            parsed.unwrap_or_else(|_| {
                panic!("VISCOROLL_SEED must be a decimal or 0x-hex u64, got `{text}`")
            })
        }
        Err(_) => {
            let nanos = std::time::SystemTime::now()
                .duration_since(std::time::UNIX_EPOCH)
                .map(|d| d.as_nanos() as u64)
                .unwrap_or(0);
            mix(nanos ^ (u64::from(std::process::id()) << 32))
        }
    })
}

/// The seed of the randomized test `test` in this run (printed with the way to reproduce it).
pub fn seed(test: &str) -> u64 {
    let base = base_seed();
    println!("{test}: random inputs from VISCOROLL_SEED={base:#x} (set it to replay this run)");
    // FNV-1a of the name, then mixed with the base seed.
    let name = test.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    });
    mix(base ^ mix(name))
}

/// SplitMix64: a small generator for the cases (the seed comes from tests/seed.rs).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    pub fn pick<'a, T>(&mut self, v: &'a [T]) -> &'a T {
        &v[self.below(v.len())]
    }
}

/// A scenes TOML with one scene whose sizes are drawn around the limits.
pub fn scene_with(
    name: &str,
    temps: usize,
    map_temps: usize,
    speeds: usize,
    cover_mm: f64,
) -> String {
    let list = |n: usize, v: f64| {
        let items: Vec<String> = (0..n).map(|k| format!("{}", v + k as f64 * 0.01)).collect();
        format!("[{}]", items.join(", "))
    };
    let mut s = format!(
        "[[scene]]\nname = \"{name}\"\nroll_radius_mm = 100.0\nload_n_per_m = 2000.0\nspeed_m_s = 1.0\ntemps_c = {}\n",
        list(temps, 0.0)
    );
    if map_temps > 0 {
        s += &format!("map_temps_c = {}\n", list(map_temps, 0.0));
        s += &format!("map_speeds_m_s = {}\n", list(speeds, 1.0));
    }
    if cover_mm > 0.0 {
        s += &format!("cover_thickness_mm = {cover_mm:e}\n");
    }
    s
}
