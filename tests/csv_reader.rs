//! The `cor --input` reader (`batch::parse_rows`): every data line becomes a row with its
//! physical line number, or the run is refused with an error naming that line; blank lines are
//! skipped and reported; no raw control byte ever reaches a message.

use mdr_impact::apps::batch::{format_line_list, parse_rows, Rows};
use mdr_impact::{Error, Groups};

/// Rows as (line, fields) pairs.
fn rows_of(r: &Rows) -> Vec<(u64, [&str; 3])> {
    r.rows
        .iter()
        .map(|row| {
            (
                row.line,
                [
                    row.text[0].as_str(),
                    row.text[1].as_str(),
                    row.text[2].as_str(),
                ],
            )
        })
        .collect()
}

const A: [&str; 3] = ["0.45", "0.01", "1"];
const B: [&str; 3] = ["0.3", "1", "0.1"];

/// Files that are read: (case, bytes, rows as (line, fields), skipped blank lines).
#[allow(clippy::type_complexity)]
fn good_cases() -> Vec<(
    &'static str,
    &'static [u8],
    Vec<(u64, [&'static str; 3])>,
    Vec<u64>,
)> {
    vec![
        (
            "LF",
            b"nu,p2,p3\n0.45,0.01,1\n0.3,1,0.1\n",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "LF, no final newline",
            b"nu,p2,p3\n0.45,0.01,1\n0.3,1,0.1",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "CRLF",
            b"nu,p2,p3\r\n0.45,0.01,1\r\n0.3,1,0.1\r\n",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "CRLF, no final newline",
            b"nu,p2,p3\r\n0.45,0.01,1\r\n0.3,1,0.1",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "CR only",
            b"nu,p2,p3\r0.45,0.01,1\r0.3,1,0.1\r",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "CR only, no final newline",
            b"nu,p2,p3\r0.45,0.01,1\r0.3,1,0.1",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "mixed endings",
            b"nu,p2,p3\r\n0.45,0.01,1\n0.3,1,0.1\r",
            vec![(2, A), (3, B)],
            vec![],
        ),
        (
            "blank lines at start",
            b"\n\nnu,p2,p3\n0.45,0.01,1\n",
            vec![(4, A)],
            vec![1, 2],
        ),
        (
            "blank lines in the middle",
            b"nu,p2,p3\n0.45,0.01,1\n\n\n0.3,1,0.1\n",
            vec![(2, A), (5, B)],
            vec![3, 4],
        ),
        (
            "blank lines at the end",
            b"nu,p2,p3\n0.45,0.01,1\n\n\n",
            vec![(2, A)],
            vec![3, 4],
        ),
        (
            "blank line, no final newline",
            b"nu,p2,p3\n\n0.45,0.01,1",
            vec![(3, A)],
            vec![2],
        ),
        (
            "blank lines, CRLF",
            b"\r\nnu,p2,p3\r\n\r\n0.45,0.01,1\r\n\r\n",
            vec![(4, A)],
            vec![1, 3, 5],
        ),
        (
            "blank lines, CR only",
            b"nu,p2,p3\r\r0.45,0.01,1\r\r",
            vec![(3, A)],
            vec![2, 4],
        ),
        (
            "UTF-8 BOM",
            b"\xEF\xBB\xBFnu,p2,p3\n0.45,0.01,1\n",
            vec![(2, A)],
            vec![],
        ),
        (
            "UTF-8 BOM, CRLF",
            b"\xEF\xBB\xBFnu,p2,p3\r\n0.45,0.01,1\r\n",
            vec![(2, A)],
            vec![],
        ),
        (
            "quoted fields",
            b"\"nu\",\"p2\",\"p3\"\n\"0.45\", \"0.01\" ,\"1\"\n",
            vec![(2, A)],
            vec![],
        ),
        (
            "spaces inside quotes",
            b"nu,p2,p3\n\" 0.45 \",0.01,\"1\t\"\n",
            vec![(2, A)],
            vec![],
        ),
        (
            "fields trimmed",
            b" nu , p2 ,p3\t\n 0.45 ,\t0.01, 1 \n",
            vec![(2, A)],
            vec![],
        ),
        ("header only", b"nu,p2,p3\n", vec![], vec![]),
        (
            "elastic limit p3 = 0",
            b"nu,p2,p3\n0.3,1,0\n",
            vec![(2, ["0.3", "1", "0"])],
            vec![],
        ),
        (
            "incompressible",
            b"nu,p2,p3\n0.5,1e-3,1e2\n",
            vec![(2, ["0.5", "1e-3", "1e2"])],
            vec![],
        ),
    ]
}

/// Files that are refused: (case, bytes, line of the error, text the message contains).
fn bad_cases() -> Vec<(&'static str, &'static [u8], u64, &'static str)> {
    vec![
        (
            "bad field, LF",
            b"nu,p2,p3\n0.45,0.01,1\n0.3,1,0.1\n0.5,x,10\n",
            4,
            "p2 = 'x' is not a number",
        ),
        (
            "bad field, CRLF",
            b"nu,p2,p3\r\n0.45,0.01,1\r\n0.3,1,0.1\r\n0.5,x,10\r\n",
            4,
            "p2 = 'x'",
        ),
        (
            "bad field, CR only",
            b"nu,p2,p3\r0.45,0.01,1\r0.3,1,0.1\r0.5,x,10\r",
            4,
            "p2 = 'x'",
        ),
        (
            "bad field after blank lines",
            b"nu,p2,p3\n\n\n0.5,x,10\n",
            4,
            "p2 = 'x'",
        ),
        (
            "bad field after blank lines, CRLF",
            b"nu,p2,p3\r\n\r\n\r\n0.5,x,10\r\n",
            4,
            "p2 = 'x'",
        ),
        (
            "bad field after blank lines, CR",
            b"nu,p2,p3\r\r\r0.5,x,10",
            4,
            "p2 = 'x'",
        ),
        (
            "bad field after BOM",
            b"\xEF\xBB\xBFnu,p2,p3\n0.5,x,10\n",
            2,
            "p2 = 'x'",
        ),
        (
            "NUL in a field",
            b"nu,p2,p3\n0.45,0.0\x001,1\n",
            2,
            "p2 = '0.0\\01'",
        ),
        (
            "BEL in a field",
            b"nu,p2,p3\n0.45,0.01,1\x07\n",
            2,
            "p3 = '1\\u{7}'",
        ),
        (
            "ESC in a field",
            b"nu,p2,p3\n\x1b[31m0.45,0.01,1\n",
            2,
            "nu = '\\u{1b}[31m0.45'",
        ),
        (
            "BOM after the start",
            b"nu,p2,p3\n\xEF\xBB\xBF0.45,0.01,1\n",
            2,
            "nu = '\\u{feff}0.45'",
        ),
        (
            "invalid UTF-8",
            b"nu,p2,p3\n0.45,0.01,1\n0.3,\xff,1\n",
            3,
            "not valid UTF-8 (byte 5",
        ),
        (
            "invalid UTF-8 in the header",
            b"nu,p2,\xfe\n0.45,0.01,1\n",
            1,
            "not valid UTF-8",
        ),
        (
            "missing field",
            b"nu,p2,p3\n0.45,0.01,1\n0.45,0.01\n",
            3,
            "expected 3 fields (nu,p2,p3), found 2",
        ),
        (
            "extra field",
            b"nu,p2,p3\n0.45,0.01,1,2\n",
            2,
            "expected 3 fields (nu,p2,p3), found 4",
        ),
        ("trailing comma", b"nu,p2,p3\n0.45,0.01,1,\n", 2, "found 4"),
        (
            "commas only",
            b"nu,p2,p3\n0.45,0.01,1\n,,\n",
            3,
            "nu is empty",
        ),
        ("one comma", b"nu,p2,p3\n,\n", 2, "found 2"),
        (
            "whitespace only",
            b"nu,p2,p3\n0.45,0.01,1\n  \t\n0.3,1,0.1\n",
            3,
            "only whitespace",
        ),
        ("empty field", b"nu,p2,p3\n0.45,,1\n", 2, "p2 is empty"),
        (
            "empty quoted field",
            b"nu,p2,p3\n0.45,\"\",1\n",
            2,
            "p2 is empty",
        ),
        (
            "wrong header",
            b"nu,p2\n0.45,0.01\n",
            1,
            "header must be 'nu,p2,p3', found 'nu,p2'",
        ),
        (
            "header in capitals",
            b"NU,P2,P3\n0.45,0.01,1\n",
            1,
            "found 'NU,P2,P3'",
        ),
        (
            "header with an extra column",
            b"nu,p2,p3,x\n0.45,0.01,1,2\n",
            1,
            "found 'nu,p2,p3,x'",
        ),
        (
            "header in another order",
            b"p2,nu,p3\n0.01,0.45,1\n",
            1,
            "found 'p2,nu,p3'",
        ),
        ("no header", b"0.45,0.01,1\n", 1, "header must be"),
        (
            "header after blank lines",
            b"\n\nnu,p3\n",
            3,
            "header must be",
        ),
        (
            "header with a control byte",
            b"nu\x00,p2,p3\n0.45,0.01,1\n",
            1,
            "found 'nu\\0,p2,p3'",
        ),
        (
            "whitespace line before the header",
            b"  \nnu,p2,p3\n",
            1,
            "header must be",
        ),
        ("empty file", b"", 1, "no header"),
        ("blank lines only", b"\n\r\n\r", 1, "no header"),
        ("BOM only", b"\xEF\xBB\xBF", 1, "no header"),
        (
            "unterminated quote",
            b"nu,p2,p3\n\"0.45,0.01,1\n0.3,1,0.1\n",
            2,
            "unterminated quoted field",
        ),
        (
            "quoted field across lines",
            b"nu,p2,p3\n\"0.\n45\",0.01,1\n",
            2,
            "cannot span lines",
        ),
        (
            "quoted field across lines, CRLF",
            b"nu,p2,p3\r\n0.45,0.01,\"1\r\n\"\r\n",
            2,
            "cannot span lines",
        ),
        (
            "text after a quoted field",
            b"nu,p2,p3\n\"0.45\"x,0.01,1\n",
            2,
            "unexpected text 'x,0.01,1' after a quoted field",
        ),
        (
            "nu above 0.5",
            b"nu,p2,p3\n0.5000001,1,1\n",
            2,
            "nu = 5.000001e-1 is out of range",
        ),
        (
            "p3 negative",
            b"nu,p2,p3\n0.3,1,-1\n",
            2,
            "p3 = -1e0 is out of range",
        ),
        (
            "p2 zero",
            b"nu,p2,p3\n0.3,0,1\n",
            2,
            "p2 = 0e0 is out of range",
        ),
        (
            "p2 inf",
            b"nu,p2,p3\n0.3,inf,1\n",
            2,
            "p2 = 'inf' is not a finite number",
        ),
        (
            "p2 1e999",
            b"nu,p2,p3\n0.3,1e999,1\n",
            2,
            "p2 = '1e999' is not a finite number",
        ),
        (
            "p3 -inf",
            b"nu,p2,p3\n0.3,1,-inf\n",
            2,
            "p3 = '-inf' is not a finite number",
        ),
        (
            "nu NaN",
            b"nu,p2,p3\nNaN,1,1\n",
            2,
            "nu = 'NaN' is not a finite number",
        ),
        (
            "p2 tiny",
            b"nu,p2,p3\n0.3,1e-310,1\n",
            2,
            "p2 = 1e-310 is out of range",
        ),
    ]
}

#[test]
fn csv_reader_reads_every_data_line_with_its_physical_line_number() {
    for (case, bytes, rows, skipped) in good_cases() {
        let r = parse_rows("in.csv", bytes).unwrap_or_else(|e| panic!("{case}: {e}"));
        assert_eq!(rows_of(&r), rows, "{case}");
        assert_eq!(r.skipped_blank_lines, skipped, "{case}");
        for row in &r.rows {
            let v: Vec<f64> = row.text.iter().map(|t| t.parse().unwrap()).collect();
            assert_eq!(row.groups, Groups::new(v[0], v[1], v[2]).unwrap(), "{case}");
        }
    }
}

#[test]
fn csv_reader_refuses_bad_lines_naming_the_physical_line() {
    for (case, bytes, line, needle) in bad_cases() {
        match parse_rows("in.csv", bytes) {
            Err(e @ Error::Csv { .. }) => {
                let Error::Csv {
                    file,
                    line: got,
                    message,
                } = &e
                else {
                    unreachable!()
                };
                assert_eq!(file, "in.csv", "{case}");
                assert_eq!(*got, line, "{case}: {message}");
                assert!(
                    message.contains(needle),
                    "{case}: '{needle}' not in '{message}'"
                );
                let shown = e.to_string();
                assert!(
                    !shown.chars().any(char::is_control),
                    "{case}: raw control character in {shown:?}"
                );
                assert!(
                    shown.starts_with(&format!("in.csv:{line}: ")),
                    "{case}: {shown}"
                );
            }
            other => panic!("{case}: expected Error::Csv, got {other:?}"),
        }
    }
}

#[test]
fn csv_reader_line_list_format() {
    assert_eq!(format_line_list(&[]), "");
    assert_eq!(format_line_list(&[3]), "3");
    assert_eq!(format_line_list(&[3, 4]), "3, 4");
    assert_eq!(format_line_list(&[3, 4, 5, 9]), "3-5, 9");
    assert_eq!(
        format_line_list(&[1, 3, 5, 6, 7, 8, 10, 11]),
        "1, 3, 5-8, 10, 11"
    );
}

/// The data lines are parsed in parallel: with several bad lines in a long file the error still
/// names the first in file order, and every good row keeps its line and order.
#[test]
fn csv_reader_names_the_first_bad_line_of_a_long_file() {
    let mut text = String::from("nu,p2,p3\n");
    for i in 0..20_000 {
        match i {
            12_345 => text.push_str("0.3,abc,1\n"),
            15_000 => text.push_str("0.3,1\n"),
            17_000 => text.push_str("2,1,1\n"),
            _ => text.push_str(&format!("0.3,{},1\n", 1 + i)),
        }
    }
    match parse_rows("long.csv", text.as_bytes()) {
        Err(Error::Csv { line, message, .. }) => {
            assert_eq!(line, 12_347, "{message}");
            assert!(message.contains("p2 = 'abc' is not a number"), "{message}");
        }
        other => panic!("expected the error of line 12347, got {other:?}"),
    }
    let good: String = text
        .lines()
        .enumerate()
        .filter(|(i, _)| ![12_346, 15_001, 17_001].contains(i))
        .map(|(_, l)| format!("{l}\n"))
        .collect();
    let rows = parse_rows("long.csv", good.as_bytes()).unwrap();
    assert_eq!(rows.rows.len(), 19_997);
    for (k, r) in rows.rows.iter().enumerate() {
        assert_eq!(r.line, k as u64 + 2);
        assert_eq!(r.text[1].parse::<u64>().unwrap() as f64, r.groups.p2);
    }
    assert!(rows
        .rows
        .windows(2)
        .all(|w| w[0].groups.p2 < w[1].groups.p2));
}

/// `write_results` formats chunks of rows in parallel: its bytes are those of one CSV writer
/// over every row, in input order (more rows than one chunk, elastic rows answered in closed
/// form so that the test is quick).
#[test]
fn result_table_of_parallel_chunks_is_one_writer_s_table() {
    use mdr_impact::apps::batch::{solve_rows, write_results, OUTPUT_HEADER};
    let mut text = String::from("nu,p2,p3\n");
    for i in 0..10_001 {
        text.push_str(&format!("{},{},0\n", 0.5 - 1e-4 * i as f64, 1.0 + i as f64));
    }
    let rows = parse_rows("elastic.csv", text.as_bytes()).unwrap().rows;
    let outcomes = solve_rows("elastic.csv", &rows, &Default::default()).unwrap();
    let mut got = Vec::new();
    write_results(&mut got, &rows, &outcomes).unwrap();
    let mut one = csv::Writer::from_writer(Vec::new());
    one.write_record(OUTPUT_HEADER).unwrap();
    for (r, o) in rows.iter().zip(&outcomes) {
        let f = |x: f64| format!("{x:e}");
        one.write_record([
            r.text[0].clone(),
            r.text[1].clone(),
            r.text[2].clone(),
            f(o.cor),
            f(o.contact_time),
            f(o.max_indentation),
        ])
        .unwrap();
    }
    let want = one.into_inner().unwrap();
    assert_eq!(
        String::from_utf8(got).unwrap(),
        String::from_utf8(want).unwrap()
    );
}
