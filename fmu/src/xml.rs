//! `modelDescription.xml` and the GUID, both generated from [`crate::model::variables`].

use crate::model::{variables, BaseType, Causality, Variability, Variable};
use std::fmt::Write as _;
use std::sync::OnceLock;
use wrc_kernel::table::{fnv1a, FNV_OFFSET};

/// The FMU's model identifier (the shared library is `binaries/<platform>/wrc.so`).
pub const MODEL_IDENTIFIER: &str = "wrc";

/// Log categories the FMU sends messages in (not filtered by fmi2SetDebugLogging, which only
/// switches `logAll` on and off).
pub const LOG_CATEGORIES: [(&str, &str); 3] = [
    (
        "logStatusWarning",
        "steps that failed (see the status output)",
    ),
    ("logStatusError", "refused calls"),
    ("logAll", "debug messages (with fmi2SetDebugLogging on)"),
];

/// The model variables, built once.
pub fn vars() -> &'static [Variable] {
    static V: OnceLock<Vec<Variable>> = OnceLock::new();
    V.get_or_init(variables)
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn causality(c: Causality) -> &'static str {
    match c {
        Causality::Input => "input",
        Causality::Parameter => "parameter",
        Causality::Output => "output",
    }
}

fn variability(v: Variability) -> &'static str {
    match v {
        Variability::Continuous => "continuous",
        Variability::Discrete => "discrete",
        Variability::Fixed => "fixed",
        Variability::Tunable => "tunable",
    }
}

/// The `ModelVariables` and `ModelStructure` elements (everything the GUID depends on).
fn body(vars: &[Variable]) -> String {
    let mut s = String::from("  <ModelVariables>\n");
    for (vr, v) in vars.iter().enumerate() {
        let _ = writeln!(
            s,
            "    <!-- index {} -->\n    <ScalarVariable name=\"{}\" valueReference=\"{vr}\" \
             description=\"{}\" causality=\"{}\" variability=\"{}\"{}>",
            vr + 1,
            escape(&v.name),
            escape(&v.description),
            causality(v.causality),
            variability(v.variability),
            match (v.causality, v.start) {
                (Causality::Parameter, Some(_)) => " initial=\"exact\"",
                _ => "",
            }
        );
        let start = v
            .start
            .map(|x| format!(" start=\"{x:?}\""))
            .unwrap_or_default();
        match v.base {
            BaseType::Real => {
                let unit = if v.unit.is_empty() {
                    String::new()
                } else {
                    format!(" unit=\"{}\"", escape(v.unit))
                };
                let _ = writeln!(s, "      <Real{unit}{start}/>");
            }
            BaseType::Integer => {
                let _ = writeln!(s, "      <Integer{start}/>");
            }
        }
        s.push_str("    </ScalarVariable>\n");
    }
    s.push_str("  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n");
    for (vr, v) in vars.iter().enumerate() {
        if v.causality == Causality::Output {
            // Every output depends directly on every input (an algebraic step), the default.
            let _ = writeln!(s, "      <Unknown index=\"{}\"/>", vr + 1);
        }
    }
    // Outputs are calculated during initialisation too (fmi2ExitInitializationMode evaluates).
    s.push_str("    </Outputs>\n    <InitialUnknowns>\n");
    for (vr, v) in vars.iter().enumerate() {
        if v.causality == Causality::Output {
            let _ = writeln!(s, "      <Unknown index=\"{}\"/>", vr + 1);
        }
    }
    s.push_str("    </InitialUnknowns>\n  </ModelStructure>\n");
    s
}

/// The GUID: FNV-1a of the variables' declarations and the crate version, formatted as a UUID,
/// so that an FMU whose description and library disagree is refused by `fmi2Instantiate`.
pub fn guid() -> &'static str {
    static G: OnceLock<String> = OnceLock::new();
    G.get_or_init(|| {
        let b = body(vars());
        let seed = fnv1a(FNV_OFFSET, env!("CARGO_PKG_VERSION").as_bytes());
        let a = fnv1a(seed, b.as_bytes());
        let c = fnv1a(a ^ 0x5bd1_e995, b.as_bytes());
        let x = ((a as u128) << 64) | c as u128;
        let h = format!("{x:032x}");
        format!(
            "{{{}-{}-{}-{}-{}}}",
            &h[0..8],
            &h[8..12],
            &h[12..16],
            &h[16..20],
            &h[20..32]
        )
    })
}

/// The FMI 2.0 `modelDescription.xml` (co-simulation).
pub fn model_description() -> String {
    let units: Vec<&str> = {
        let mut u: Vec<&str> = vars()
            .iter()
            .map(|v| v.unit)
            .filter(|u| !u.is_empty())
            .collect();
        u.sort_unstable();
        u.dedup();
        u
    };
    let mut s = String::new();
    let _ = write!(
        s,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <fmiModelDescription fmiVersion=\"2.0\" modelName=\"wrc\" guid=\"{}\" \
         description=\"wrc real-time wheel-rail contact step of one wheel on a contact table\" \
         generationTool=\"wrc\" version=\"{}\" variableNamingConvention=\"flat\" \
         numberOfEventIndicators=\"0\">\n\
         \x20 <CoSimulation modelIdentifier=\"{MODEL_IDENTIFIER}\" needsExecutionTool=\"false\" \
         canHandleVariableCommunicationStepSize=\"true\" canInterpolateInputs=\"false\" \
         maxOutputDerivativeOrder=\"0\" canRunAsynchronuously=\"false\" \
         canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"true\" \
         canGetAndSetFMUstate=\"false\" canSerializeFMUstate=\"false\" \
         providesDirectionalDerivative=\"false\"/>\n",
        guid(),
        env!("CARGO_PKG_VERSION")
    );
    s.push_str("  <UnitDefinitions>\n");
    for u in units {
        let _ = writeln!(s, "    <Unit name=\"{}\"/>", escape(u));
    }
    s.push_str("  </UnitDefinitions>\n");
    s.push_str("  <LogCategories>\n");
    for (name, d) in LOG_CATEGORIES {
        let _ = writeln!(s, "    <Category name=\"{name}\" description=\"{d}\"/>");
    }
    s.push_str("  </LogCategories>\n");
    s.push_str("  <DefaultExperiment startTime=\"0.0\" stopTime=\"2.0\" stepSize=\"0.001\"/>\n");
    s.push_str(&body(vars()));
    s.push_str("</fmiModelDescription>\n");
    s
}
