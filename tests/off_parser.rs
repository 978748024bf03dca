//! The OFF reader never panics, whatever it is fed, and reads back exactly
//! what the writer wrote.

use motion_bound::{Float, MeshError, TriMesh};
use proptest::prelude::*;

fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2048);
    ProptestConfig::with_cases(cases)
}

/// Parses in both precisions; only errors or meshes may come out.
fn parse_both(text: &str) {
    let a = TriMesh::<f64>::from_off_str(text);
    let b = TriMesh::<f32>::from_off_str(text);
    // Whatever one precision accepts is well formed for the other, unless a
    // coordinate is beyond f32's range.
    if let (Ok(_), Err(e)) = (&a, &b) {
        assert!(
            matches!(e, MeshError::Off(_)),
            "f64 accepted what f32 rejected for another reason: {e}"
        );
    }
}

/// Text made of OFF-like tokens and line breaks: reaches the parser's later
/// states far more often than random bytes.
fn off_like() -> impl Strategy<Value = String> {
    let token = prop_oneof![
        Just("OFF".to_string()),
        Just("COFF".to_string()),
        Just("#".to_string()),
        Just("\n".to_string()),
        Just("\n".to_string()),
        Just("\r\n".to_string()),
        Just("3".to_string()),
        Just("4".to_string()),
        (0u32..6).prop_map(|i| i.to_string()),
        any::<u32>().prop_map(|i| i.to_string()),
        any::<i64>().prop_map(|i| i.to_string()),
        any::<f64>().prop_map(|x| format!("{x:?}")),
        Just("nan".to_string()),
        Just("-inf".to_string()),
        Just("1e999".to_string()),
        "[ \t]{0,3}",
        "[a-z.+-]{1,4}",
    ];
    (
        prop_oneof![
            Just("OFF\n"),
            Just("OFF 3 1 0\n"),
            Just(""),
            Just("OFF\n3 1 0\n")
        ],
        prop::collection::vec(token, 0..60),
    )
        .prop_map(|(head, tokens)| {
            let mut s = String::from(head);
            for t in tokens {
                s.push_str(&t);
                if !t.ends_with('\n') {
                    s.push(' ');
                }
            }
            s
        })
}

/// OBJ-like text: positions, faces with every index form (negative,
/// `v/t/n`, `v//n`), objects and groups.
fn obj_like() -> impl Strategy<Value = String> {
    let index = prop_oneof![
        (-4i64..8).prop_map(|i| i.to_string()),
        any::<i64>().prop_map(|i| i.to_string()),
        (1u32..5, 1u32..5).prop_map(|(a, b)| format!("{a}//{b}")),
        (1u32..5, 1u32..5, 1u32..5).prop_map(|(a, b, c)| format!("{a}/{b}/{c}")),
        Just("/".to_string()),
    ];
    let number = prop_oneof![
        (-10.0f64..10.0).prop_map(|x| x.to_string()),
        any::<f64>().prop_map(|x| format!("{x:?}")),
        Just("nan".to_string()),
        Just("1e999".to_string()),
    ];
    let line = prop_oneof![
        4 => prop::collection::vec(number.clone(), 0..5)
            .prop_map(|xs| format!("v {}", xs.join(" "))),
        4 => prop::collection::vec(index, 0..6).prop_map(|xs| format!("f {}", xs.join(" "))),
        1 => prop::collection::vec(number, 0..4).prop_map(|xs| format!("vn {}", xs.join(" "))),
        1 => Just("o part".to_string()),
        1 => Just("g".to_string()),
        1 => Just("mtllib missing.mtl".to_string()),
        1 => "[ -~]{0,12}",
    ];
    prop::collection::vec(line, 0..30).prop_map(|lines| lines.join("\n"))
}

/// Coordinates biased to what could break a writer or a reader: signed
/// zeros, subnormals, the range limits, long decimal expansions.
fn coordinate<T: Float>() -> impl Strategy<Value = f64> {
    let max = T::MAX_INPUT.to_f64();
    // Decimal exponents from the subnormals to MAX_INPUT.
    let (lo, hi) = (T::ETA.to_f64().log10() as i32, max.log10() as i32);
    prop_oneof![
        4 => -10.0f64..10.0,
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => Just(max),
        1 => Just(-max),
        1 => Just(T::ETA.to_f64()),
        1 => -max..max,
        1 => (lo..hi).prop_map(|e| 1.2345678901234567 * 10f64.powi(e)),
    ]
}

fn mesh<T: Float>() -> impl Strategy<Value = TriMesh<T>> {
    prop::collection::vec(
        [coordinate::<T>(), coordinate::<T>(), coordinate::<T>()],
        1..40,
    )
    .prop_flat_map(|vs| {
        let n = vs.len() as u32;
        (Just(vs), prop::collection::vec([0..n, 0..n, 0..n], 1..40))
    })
    .prop_filter_map("coordinates within T's range", |(vs, ts)| {
        let vs: Vec<[T; 3]> = vs.iter().map(|v| v.map(T::from_f64)).collect();
        TriMesh::try_new(vs, ts).ok()
    })
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        parse_both(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn off_like_text_never_panics(text in off_like()) {
        parse_both(&text);
    }

    #[test]
    fn arbitrary_bytes_never_panic_the_obj_reader(
        bytes in prop::collection::vec(any::<u8>(), 0..512)
    ) {
        let _ = TriMesh::<f64>::from_obj_str(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn obj_like_text_never_panics(text in obj_like()) {
        let _ = TriMesh::<f64>::from_obj_str(&text);
        let _ = TriMesh::<f32>::from_obj_str(&text);
    }

    #[test]
    fn f64_round_trip_is_exact(m in mesh::<f64>()) {
        let text = m.to_off_string();
        let back = TriMesh::<f64>::from_off_str(&text).unwrap();
        prop_assert_eq!(back.triangles(), m.triangles());
        for (a, b) in back.vertices().iter().zip(m.vertices()) {
            // Bits, so that -0.0 and 0.0 are told apart.
            prop_assert_eq!(a.map(f64::to_bits), b.map(f64::to_bits));
        }
    }

    #[test]
    fn f32_round_trip_is_exact(m in mesh::<f32>()) {
        let back = TriMesh::<f32>::from_off_str(&m.to_off_string()).unwrap();
        prop_assert_eq!(back.triangles(), m.triangles());
        for (a, b) in back.vertices().iter().zip(m.vertices()) {
            prop_assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits));
        }
    }
}
