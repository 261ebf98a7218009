//! The contract's names of a list's choices (`roller`, `cycloidal`,
//! `revolute`…) as a Spanish lab writes them: in any case, with or without
//! accents, with spaces or underscores for hyphens, or in Spanish
//! ("rodillo", "Cicloidal", "par de revolución" is not one: "revolución"
//! is). A name is read only as one of the choices the field has, so one
//! Spanish word may stand for different names in different lists ("plano":
//! a flat face, a planar count; "punto": a point curve, a decimal point).

/// Spanish words (written as [`fold`] leaves them) and the contract's name
/// each stands for, where the field has it among its choices. The course's
/// words (seeds 000–020) and their common variants.
const SPANISH: &[(&str, &str)] = &[
    // A cam's follower, its motion and sense (seed 012).
    ("rodillo", "roller"),
    ("de-rodillo", "roller"),
    ("de-cara-plana", "flat"),
    ("pie-plano", "flat"),
    ("de-pie-plano", "flat"),
    ("de-cuchilla", "knife"),
    ("plano", "flat"),
    ("plana", "flat"),
    ("cara-plana", "flat"),
    ("cuchilla", "knife"),
    ("puntual", "knife"),
    ("punta", "knife"),
    ("traslacion", "translating"),
    ("traslacional", "translating"),
    ("de-traslacion", "translating"),
    ("oscilante", "oscillating"),
    ("basculante", "oscillating"),
    ("antihorario", "ccw"),
    ("horario", "cw"),
    ("sentido-antihorario", "ccw"),
    ("sentido-horario", "cw"),
    // A cam's laws.
    ("reposo", "dwell"),
    ("detencion", "dwell"),
    ("armonico", "harmonic"),
    ("armonica", "harmonic"),
    ("cicloidal", "cycloidal"),
    ("polinomico-345", "polynomial-345"),
    ("polinomica-345", "polynomial-345"),
    ("polinomial-345", "polynomial-345"),
    ("polinomico-4567", "polynomial-4567"),
    ("polinomica-4567", "polynomial-4567"),
    ("polinomial-4567", "polynomial-4567"),
    // The laws as the plots' labels and the course write them ("polinómica 3-4-5").
    ("polinomica-3-4-5", "polynomial-345"),
    ("polinomico-3-4-5", "polynomial-345"),
    ("polynomial-3-4-5", "polynomial-345"),
    ("polinomica-4-5-6-7", "polynomial-4567"),
    ("polinomico-4-5-6-7", "polynomial-4567"),
    ("polynomial-4-5-6-7", "polynomial-4567"),
    ("seno-modificado", "modified-sine"),
    ("senoidal-modificada", "modified-sine"),
    ("trapecio-modificado", "modified-trapezoid"),
    ("trapezoidal-modificada", "modified-trapezoid"),
    // Joints, loads and curves of a mechanism.
    ("revolucion", "revolute"),
    ("de-revolucion", "revolute"),
    ("rotacion", "revolute"),
    ("articulacion", "revolute"),
    ("prismatico", "prismatic"),
    ("prismatica", "prismatic"),
    ("cilindrico", "cylindrical"),
    ("cilindrica", "cylindrical"),
    ("esferico", "spherical"),
    ("esferica", "spherical"),
    ("rotula", "spherical"),
    ("cardan", "universal"),
    ("junta-cardan", "universal"),
    ("junta-de-cardan", "universal"),
    ("junta-de-hooke", "universal"),
    ("junta-universal", "universal"),
    ("esfera-en-cilindro", "sphere-in-cylinder"),
    ("esfera-cilindro", "sphere-in-cylinder"),
    // A spatial input's coordinate.
    ("giro", "rotation"),
    ("rotacion", "rotation"),
    ("deslizamiento", "slide"),
    ("desplazamiento", "slide"),
    ("traslacion", "slide"),
    ("pasador-ranura", "pin-slot"),
    ("pasador-en-ranura", "pin-slot"),
    ("engranaje", "gear"),
    ("contacto", "contact"),
    ("fuerza", "force"),
    ("par", "torque"),
    ("momento", "torque"),
    ("muelle", "spring"),
    ("resorte", "spring"),
    ("amortiguador", "damper"),
    ("punto", "point"),
    ("recta", "line"),
    ("linea", "line"),
    ("circunferencia", "circle"),
    ("circulo", "circle"),
    ("leva", "cam"),
    // A kinetostatics job's outputs.
    ("motor", "driving"),
    ("par-motor", "driving"),
    ("reacciones", "reactions"),
    ("cinematica", "kinematics"),
    ("reducidas", "reduced"),
    ("reducido", "reduced"),
    ("condicion", "condition"),
    ("energia", "energy"),
    ("energias", "energy"),
    ("puntos", "points"),
    ("sacudimiento", "shaking"),
    // Tables, interpolation, mobility.
    ("lineal", "linear"),
    ("escalon", "step"),
    ("plano", "planar"),
    ("plana", "planar"),
    ("espacial", "spatial"),
    ("grados", "deg"),
    ("radianes", "rad"),
    ("coma", "comma"),
];

/// `text` lowercased, its Spanish accents and ñ taken off, spaces and
/// underscores written as hyphens, trimmed.
pub fn fold(text: &str) -> String {
    text.trim()
        .chars()
        .flat_map(char::to_lowercase)
        .map(|c| match c {
            'á' | 'à' => 'a',
            'é' | 'è' => 'e',
            'í' => 'i',
            'ó' => 'o',
            'ú' | 'ü' => 'u',
            'ñ' => 'n',
            ' ' | '_' => '-',
            c => c,
        })
        .collect()
}

/// The one name of `choices` that `text` writes ([module](self)), or None
/// (none, or more than one).
pub fn read<'a>(text: &str, choices: &[&'a str]) -> Option<&'a str> {
    let folded = fold(text);
    let mut meant = choices.iter().copied().filter(|name| {
        fold(name) == folded || SPANISH.iter().any(|&(word, english)| word == folded && english == *name)
    });
    match (meant.next(), meant.next()) {
        (Some(name), None) => Some(name),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FOLLOWERS: [&str; 3] = ["flat", "roller", "knife"];

    /// Case, accents, spaces and Spanish words, each only among the field's
    /// own choices; a name that is none, or any word outside them, is not read.
    #[test]
    fn a_choice_is_read_in_any_case_accent_or_spanish() {
        assert_eq!(read("Rodillo", &FOLLOWERS), Some("roller"));
        assert_eq!(read(" ROLLER ", &FOLLOWERS), Some("roller"));
        assert_eq!(read("plano", &FOLLOWERS), Some("flat"));
        assert_eq!(read("plano", &["planar", "spatial"]), Some("planar"));
        assert_eq!(read("Armónico", &["dwell", "harmonic"]), Some("harmonic"));
        assert_eq!(read("Polinómico 345", &["polynomial-345", "polynomial-4567"]), Some("polynomial-345"));
        assert_eq!(read("polinómica 4-5-6-7", &["polynomial-345", "polynomial-4567"]), Some("polynomial-4567"));
        assert_eq!(read("pin_slot", &["revolute", "pin-slot"]), Some("pin-slot"));
        let spatial = ["revolute", "prismatic", "cylindrical", "spherical", "universal", "sphere-in-cylinder"];
        assert_eq!(read("Esférico", &spatial), Some("spherical"));
        assert_eq!(read("junta cardán", &spatial), Some("universal"));
        assert_eq!(read("Cilíndrica", &spatial), Some("cylindrical"));
        assert_eq!(read("esfera en cilindro", &spatial), Some("sphere-in-cylinder"));
        assert_eq!(read("rotación", &spatial), Some("revolute"));
        assert_eq!(read("rotación", &["rotation", "slide"]), Some("rotation"));
        assert_eq!(read("Desplazamiento", &["rotation", "slide"]), Some("slide"));
        assert_eq!(read("rodillos", &FOLLOWERS), None);
        assert_eq!(read("reposo", &FOLLOWERS), None);
    }

    /// Every Spanish word is written as [`fold`] leaves it (else it could
    /// never match), and no word stands twice for the same name.
    #[test]
    fn every_word_is_folded_and_listed_once() {
        for (k, &(word, english)) in SPANISH.iter().enumerate() {
            assert_eq!(fold(word), word, "{word}");
            assert!(!SPANISH[..k].contains(&(word, english)), "{word} twice");
        }
    }
}
