//! The `draw_cost` example's arguments: a back end and a workload, each
//! named in a one-line error when it is not one the driver knows.

#[allow(dead_code)] // the workload itself, run by the example's `main`
#[path = "../examples/draw_cost.rs"]
mod tool;

use std::ffi::OsString;

use tool::shared::Failure;
use tool::{BackEnd, Through, Workload};
use wellspread::{PixelSamplerKind, SamplerKind};

fn parse(args: &[&str]) -> Result<Option<tool::Args>, Failure> {
    tool::parse(args.iter().map(OsString::from), &mut Vec::new())
}

#[test]
fn back_ends_and_workloads_parse() {
    let Ok(Some(args)) = parse(&["sobol", "2d-any"]) else {
        panic!("sobol 2d-any must parse");
    };
    let sobol = PixelSamplerKind::Padded(SamplerKind::Sobol);
    assert_eq!(args.back_end, BackEnd::Sampler(sobol));
    assert_eq!(args.workload, (Workload::TwoD, Through::Any));
    let Ok(Some(args)) = parse(&["unit", "path"]) else {
        panic!("unit path must parse");
    };
    assert_eq!(
        (args.back_end, args.workload),
        (BackEnd::Unit, (Workload::Path, Through::Static))
    );
    let Ok(Some(args)) = parse(&["sobol", "path-any-owned"]) else {
        panic!("sobol path-any-owned must parse");
    };
    assert_eq!(args.workload, (Workload::Path, Through::AnyOwned));
    let Ok(Some(args)) = parse(&["Blue-Noise", "loop"]) else {
        panic!("names parse in any case");
    };
    assert_eq!(args.back_end, BackEnd::Sampler(PixelSamplerKind::BlueNoise));
}

#[test]
fn bad_names_are_one_line_input_errors() {
    for (args, named) in [
        (&["sobl", "2d"][..], "\"sobl\""),
        (&["sobol", "3d"][..], "\"3d\""),
        (&["sobol", "2d-anyway"][..], "\"2d-anyway\""),
        (&["sobol"][..], "<WORKLOAD>"),
    ] {
        let Err(Failure::Input(message)) = parse(args) else {
            panic!("{args:?} must be an input error");
        };
        assert!(message.contains(named), "{args:?}: {message}");
        assert!(!message.contains('\n'), "one line: {message:?}");
    }
}
