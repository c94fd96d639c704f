//! Pre-check of a BIFF `.xls` workbook (an OLE2 compound file) before `calamine` opens it.
//!
//! calamine 0.31 allocates each sheet as a dense rows × columns array spanning the sheet's cell
//! addresses (and reserves rows × columns for the `DIMENSIONS` record). One damaged cell address or
//! dimension can ask for hundreds of gigabytes, which aborts the process instead of returning an
//! error. This module walks the compound file (header, DIFAT, FAT, directory, mini stream) to the
//! `Workbook` stream, then the BIFF records of each sheet the way calamine does (from the
//! `BOUNDSHEET` offsets to `EOF`), and refuses a sheet whose extent exceeds what an Excel 97–2003
//! sheet can hold (65 536 rows × 256 columns). It also refuses what would make calamine's compound-file
//! reader allocate without bound: header sizes far beyond the file, sector ids past its end, looping
//! chains. Files calamine refuses by itself (bad signature, no workbook stream) pass through to it.
//! Format: [MS-CFB] §2.2–2.6 and [MS-XLS] §2.4 (record numbers as in calamine's xls.rs).

/// The largest sheet BIFF8 can describe: 65 536 rows × 256 columns.
pub(crate) const MAX_CELLS: u64 = 65_536 * 256;

const END_OF_CHAIN: u32 = 0xFFFF_FFFE;

fn u16_at(b: &[u8], i: usize) -> Option<u16> {
    Some(u16::from_le_bytes(b.get(i..i + 2)?.try_into().ok()?))
}

fn u32_at(b: &[u8], i: usize) -> Option<u32> {
    Some(u32::from_le_bytes(b.get(i..i + 4)?.try_into().ok()?))
}

struct Cfb<'a> {
    b: &'a [u8],
    ssz: usize,
    fat: Vec<u32>,
}

type Check<T> = Result<T, String>;

impl Cfb<'_> {
    /// A sector; calamine grows its buffer to (id + 1)·size for any id it is given, so an id past
    /// the end of the file is refused here.
    fn sector(&self, id: u32) -> Check<&[u8]> {
        let off = (id as usize + 1) * self.ssz;
        if off >= self.b.len() {
            return Err(format!(
                "sector {id} lies beyond the end of the file ({} bytes): the file is damaged or truncated",
                self.b.len()
            ));
        }
        Ok(&self.b[off..(off + self.ssz).min(self.b.len())])
    }

    /// Follow a FAT chain as calamine does; a cycle (calamine would loop until memory runs out) or
    /// an id outside the FAT is refused.
    fn chain(&self, start: u32, max_len: usize) -> Check<Vec<u8>> {
        let mut out = Vec::new();
        let mut id = start;
        let mut steps = 0usize;
        while id != END_OF_CHAIN {
            steps += 1;
            if steps > self.fat.len() + 1 {
                return Err("a sector chain loops: the file is damaged".into());
            }
            out.extend_from_slice(self.sector(id)?);
            id = *self.fat.get(id as usize).ok_or_else(|| {
                format!("sector {id} is outside the allocation table: the file is damaged")
            })?;
        }
        if max_len > 0 {
            out.truncate(max_len);
        }
        Ok(out)
    }
}

/// The `Workbook` (or `Book`) stream of a compound file; `Ok(None)` where calamine will refuse the
/// file by itself (bad signature or sector size, no workbook stream).
fn workbook_stream(b: &[u8]) -> Check<Option<Vec<u8>>> {
    if b.len() < 512 {
        return Ok(None);
    }
    let ssz = match u16_at(b, 0x1E) {
        Some(9) => 512,
        Some(12) => 4096,
        _ => return Ok(None),
    };
    let word = |i: usize| u32_at(b, i).unwrap_or(0) as usize;
    // The largest buffer or stream a file of this size may declare.
    let limit = 16 * b.len() + (1 << 20);
    header_sizes(b, ssz, limit)?;
    let dir_len = word(0x28);
    let dir_start = u32_at(b, 0x30).unwrap_or(END_OF_CHAIN);
    let minifat_start = u32_at(b, 0x3C).unwrap_or(END_OF_CHAIN);
    let minifat_len = word(0x40);
    let difat_start = u32_at(b, 0x44).unwrap_or(END_OF_CHAIN);
    let mut cfb = Cfb {
        b,
        ssz,
        fat: Vec::new(),
    };
    cfb.fat = allocation_table(&cfb, difat_start)?;
    let dir = cfb.chain(dir_start, dir_len * ssz)?;
    let entries = directory_entries(&dir, ssz);
    let Some((_, root_start, root_len)) = entries.first().cloned() else {
        return Ok(None);
    };
    let mut mini = Vec::new();
    let mut minifat = Vec::new();
    if minifat_len > 0 {
        if root_len > limit {
            return Err(format!(
                "the mini stream declares {root_len} bytes: the file is damaged"
            ));
        }
        mini = cfb.chain(root_start, root_len)?;
        let mf = cfb.chain(minifat_start, minifat_len * ssz)?;
        minifat = (0..mf.len() / 4)
            .filter_map(|k| u32_at(&mf, 4 * k))
            .collect();
    }
    let Some((_, start, len)) = entries
        .iter()
        .find(|e| e.0 == "Workbook")
        .or_else(|| entries.iter().find(|e| e.0 == "Book"))
        .cloned()
    else {
        return Ok(None);
    };
    if len > limit {
        return Err(format!(
            "the workbook stream declares {len} bytes in a file of {}: the file is damaged",
            b.len()
        ));
    }
    if len >= 4096 {
        return cfb.chain(start, len).map(Some);
    }
    // Small streams live in the mini stream (64-byte sectors, their own FAT).
    mini_chain(&mini, &minifat, start, len).map(Some)
}

/// Buffers calamine sizes from header fields before reading anything: none may exceed `limit`.
fn header_sizes(b: &[u8], ssz: usize, limit: usize) -> Check<()> {
    let word = |i: usize| u32_at(b, i).unwrap_or(0) as usize;
    for (what, bytes) in [
        ("DIFAT", word(62).saturating_mul(4)),
        ("FAT", word(0x2C).saturating_mul(4)),
        ("directory", word(0x28).saturating_mul(ssz)),
        ("mini FAT", word(0x40).saturating_mul(ssz)),
    ] {
        if bytes > limit {
            return Err(format!(
                "the header declares a {what} of {bytes} bytes in a file of {}: the file is damaged",
                b.len()
            ));
        }
    }
    Ok(())
}

/// The file allocation table: the sectors the DIFAT lists (109 entries in the header, then a chain
/// of DIFAT sectors from `difat_start`, whose last entry links on), read in order.
fn allocation_table(cfb: &Cfb, difat_start: u32) -> Check<Vec<u32>> {
    // DIFAT: 109 entries in the header, then a chain of DIFAT sectors (its last entry links on).
    let mut difat: Vec<u32> = (0..109)
        .filter_map(|k| u32_at(cfb.b, 0x4C + 4 * k))
        .collect();
    let mut next = difat_start;
    let mut guard = 0;
    while next < 0xFFFF_FFFA {
        guard += 1;
        if guard > cfb.b.len() / cfb.ssz + 1 {
            return Err("the DIFAT chain loops: the file is damaged".into());
        }
        let s = cfb.sector(next)?;
        difat.extend((0..cfb.ssz / 4).filter_map(|k| u32_at(s, 4 * k)));
        next = difat.pop().unwrap_or(END_OF_CHAIN);
    }
    let mut fat = Vec::new();
    for &id in difat.iter().filter(|&&id| id < 0xFFFF_FFFC) {
        let s = cfb.sector(id)?;
        fat.extend((0..s.len() / 4).filter_map(|k| u32_at(s, 4 * k)));
    }
    Ok(fat)
}

/// The directory's entries (128 bytes each): name, start sector and stream length.
fn directory_entries(dir: &[u8], ssz: usize) -> Vec<(String, u32, usize)> {
    let entry = |e: &[u8]| -> Option<(String, u32, usize)> {
        let units: Vec<u16> = (0..32)
            .filter_map(|k| u16_at(e, 2 * k))
            .take_while(|&u| u != 0)
            .collect();
        let len = if ssz == 512 {
            u32_at(e, 120)? as usize
        } else {
            u64::from_le_bytes(e.get(120..128)?.try_into().ok()?) as usize
        };
        Some((String::from_utf16_lossy(&units), u32_at(e, 116)?, len))
    };
    dir.chunks(128).filter_map(entry).collect()
}

/// A stream of `len` bytes from mini sector `start` of the mini stream, following the mini FAT.
fn mini_chain(mini: &[u8], minifat: &[u32], start: u32, len: usize) -> Check<Vec<u8>> {
    let mut out = Vec::new();
    let mut id = start;
    let mut steps = 0;
    while id != END_OF_CHAIN {
        steps += 1;
        if steps > minifat.len() + 1 {
            return Err("a mini-sector chain loops: the file is damaged".into());
        }
        let off = id as usize * 64;
        if off >= mini.len() {
            return Err(format!(
                "mini sector {id} lies beyond the mini stream: the file is damaged"
            ));
        }
        out.extend_from_slice(&mini[off..(off + 64).min(mini.len())]);
        id = *minifat.get(id as usize).ok_or_else(|| {
            format!("mini sector {id} is outside the mini FAT: the file is damaged")
        })?;
    }
    out.truncate(len);
    Ok(out)
}

/// BIFF records from `pos`: (type, data), stopping at the end of the stream or a broken length.
fn records(s: &[u8], pos: usize) -> impl Iterator<Item = (u16, &[u8])> {
    let mut p = pos;
    std::iter::from_fn(move || {
        let t = u16_at(s, p)?;
        let len = u16_at(s, p + 2)? as usize;
        let d = s.get(p + 4..p + 4 + len)?;
        p += 4 + len;
        Some((t, d))
    })
}

/// Check a `.xls` workbook; `Err` names the sheet extent that is too large.
pub fn check(bytes: &[u8]) -> Result<(), String> {
    let Some(stream) = workbook_stream(bytes)? else {
        return Ok(());
    };
    let mut sheets = Vec::new();
    for (t, d) in records(&stream, 0) {
        match t {
            0x0085 => sheets.extend(u32_at(d, 0)),
            0x000A => break,
            _ => {}
        }
    }
    for pos in sheets {
        let (mut r0, mut r1, mut c0, mut c1) = (u64::MAX, 0u64, u64::MAX, 0u64);
        let mut add = |r: u64, c: u64| {
            r0 = r0.min(r);
            r1 = r1.max(r);
            c0 = c0.min(c);
            c1 = c1.max(c);
        };
        for (t, d) in records(&stream, pos as usize) {
            let rc = || Some((u16_at(d, 0)? as u64, u16_at(d, 2)? as u64));
            match t {
                0x000A => break,
                // DIMENSIONS: calamine reserves (last row − first row) × (last col − first col).
                0x0200 => {
                    let (rf, rl, cf, cl) = match d.len() {
                        10 => (
                            u16_at(d, 0).map(u64::from),
                            u16_at(d, 2).map(u64::from),
                            u16_at(d, 4),
                            u16_at(d, 6),
                        ),
                        14 => (
                            u32_at(d, 0).map(u64::from),
                            u32_at(d, 4).map(u64::from),
                            u16_at(d, 8),
                            u16_at(d, 10),
                        ),
                        _ => continue,
                    };
                    if let (Some(rf), Some(rl), Some(cf), Some(cl)) = (rf, rl, cf, cl) {
                        let cf = if cf > 0xFF || cl < cf { 0 } else { cf } as u64;
                        // calamine: rows = (last − 1) − first + 1, likewise columns.
                        let (rows, cols) =
                            (rl.abs_diff(rf).max(1), (cl as u64).abs_diff(cf).max(1));
                        if rows.saturating_mul(cols) > MAX_CELLS {
                            return Err(format!(
                                "a sheet declares {rows} rows × {cols} columns, more than an Excel 97–2003 sheet can hold: the file is damaged"
                            ));
                        }
                    }
                }
                0x0203 | 0x0204 | 0x0205 | 0x027E | 0x00FD | 0x0006 => {
                    if let Some((r, c)) = rc() {
                        add(r, c);
                    }
                }
                0x00BD => {
                    if let (Some((r, c)), Some(last)) =
                        (rc(), d.len().checked_sub(2).and_then(|i| u16_at(d, i)))
                    {
                        add(r, c);
                        add(r, last as u64);
                    }
                }
                _ => {}
            }
        }
        if r0 <= r1 {
            let (rows, cols) = (r1 - r0 + 1, c1 - c0 + 1);
            if rows.saturating_mul(cols) > MAX_CELLS {
                return Err(format!(
                    "cells span {rows} rows × {cols} columns, more than an Excel 97–2003 sheet can hold: the file is damaged"
                ));
            }
        }
    }
    Ok(())
}
