//! The EPLEXOR reader on .xlsx: the test writes the real .xls export's two sheets (`Exported Data`,
//! `Data header`) into a minimal Office Open XML workbook and reads it back: it must give the same
//! measurement as the .xls.

use crate::shipped::data;
use calamine::{open_workbook_auto, Data, Reader};
use std::io::Write;
use viscoroll::dma::{self, IngestOptions};

fn col_name(mut c: usize) -> String {
    let mut s = Vec::new();
    loop {
        s.push(b'A' + (c % 26) as u8);
        if c < 26 {
            break;
        }
        c = c / 26 - 1;
    }
    s.reverse();
    String::from_utf8(s).unwrap()
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn sheet_xml(rows: &[Vec<Data>]) -> String {
    let mut x = String::from(
        r#"<?xml version="1.0" encoding="UTF-8" standalone="yes"?><worksheet xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main"><sheetData>"#,
    );
    for (r, row) in rows.iter().enumerate() {
        x += &format!(r#"<row r="{}">"#, r + 1);
        for (c, d) in row.iter().enumerate() {
            let at = format!("{}{}", col_name(c), r + 1);
            match d {
                Data::Empty => {}
                Data::String(s) => {
                    x += &format!(
                        r#"<c r="{at}" t="inlineStr"><is><t xml:space="preserve">{}</t></is></c>"#,
                        escape(s)
                    )
                }
                // `{}` prints the shortest decimal that reads back to the same double.
                Data::Float(v) => x += &format!(r#"<c r="{at}"><v>{v}</v></c>"#),
                Data::Int(v) => x += &format!(r#"<c r="{at}"><v>{v}</v></c>"#),
                other => panic!("unexpected cell {other:?}"),
            }
        }
        x += "</row>";
    }
    x + "</sheetData></worksheet>"
}

fn xlsx_twin() -> Vec<u8> {
    let mut book = open_workbook_auto(data("pyvisco-ems-ca/freq_Eplexor_raw.xls")).unwrap();
    let sheets = ["Exported Data", "Data header"];
    let xml: Vec<String> = sheets
        .iter()
        .map(|name| {
            let range = book.worksheet_range(name).unwrap();
            sheet_xml(&range.rows().map(|r| r.to_vec()).collect::<Vec<_>>())
        })
        .collect();
    let ct = r#"<?xml version="1.0" encoding="UTF-8" standalone="yes"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types"><Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/><Default Extension="xml" ContentType="application/xml"/><Override PartName="/xl/workbook.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.sheet.main+xml"/><Override PartName="/xl/worksheets/sheet1.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml"/><Override PartName="/xl/worksheets/sheet2.xml" ContentType="application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml"/></Types>"#;
    let rels = r#"<?xml version="1.0" encoding="UTF-8" standalone="yes"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/officeDocument" Target="xl/workbook.xml"/></Relationships>"#;
    let wb = r#"<?xml version="1.0" encoding="UTF-8" standalone="yes"?><workbook xmlns="http://schemas.openxmlformats.org/spreadsheetml/2006/main" xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships"><sheets><sheet name="Exported Data" sheetId="1" r:id="rId1"/><sheet name="Data header" sheetId="2" r:id="rId2"/></sheets></workbook>"#;
    let wb_rels = r#"<?xml version="1.0" encoding="UTF-8" standalone="yes"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships"><Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/worksheet" Target="worksheets/sheet1.xml"/><Relationship Id="rId2" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/worksheet" Target="worksheets/sheet2.xml"/></Relationships>"#;
    let mut zip = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let opt =
        zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
    for (name, body) in [
        ("[Content_Types].xml", ct),
        ("_rels/.rels", rels),
        ("xl/workbook.xml", wb),
        ("xl/_rels/workbook.xml.rels", wb_rels),
        ("xl/worksheets/sheet1.xml", xml[0].as_str()),
        ("xl/worksheets/sheet2.xml", xml[1].as_str()),
    ] {
        zip.start_file(name, opt).unwrap();
        zip.write_all(body.as_bytes()).unwrap();
    }
    zip.finish().unwrap().into_inner()
}

#[test]
fn xlsx_twin_reads_to_the_same_measurement_as_the_xls() {
    let opts = IngestOptions::default();
    let xls = dma::read_files(&[data("pyvisco-ems-ca/freq_Eplexor_raw.xls")], &opts).unwrap();
    let xlsx = dma::read_bytes(&[("twin.xlsx".into(), xlsx_twin())], &opts).unwrap();
    assert_eq!(xlsx.sources[0].format, "eplexor");
    // Same isotherms, points (values, rows, flags), issues: everything but the sources.
    assert_eq!(xlsx.isotherms, xls.isotherms);
    assert_eq!(xlsx.kind, xls.kind);
    assert_eq!(xlsx.summary, xls.summary);
    assert_eq!(
        xlsx.sources[0].metadata.get("Material / Remark"),
        xls.sources[0].metadata.get("Material / Remark")
    );
    assert_eq!(xlsx.sources[0].columns, xls.sources[0].columns);
}
