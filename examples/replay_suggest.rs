//! The autocomplete replay table (issue 10): each family drawn over a canvas of about
//! 8 x 6 periods (12 periods for rows), stroke by stroke, accepting the proposals that
//! are among the strokes still to draw; then irregular dashes and freehand sketches,
//! where nothing should be proposed. `cargo run --release --example replay_suggest
//! [jitter]` (jitter as a fraction of the spacing, default 0.03).
use patternsynth::vector::exemplar::{family_list, freehand_sketch, irregular_dashes};
use patternsynth::vector::replay::replay;
use patternsynth::vector::{suggest_strokes, SuggestOptions};

fn main() {
    let jitter: f64 = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(0.03);
    let seed: u64 = std::env::var("SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(5);
    println!("jitter {jitter} of the spacing; canvases of 8 x 6 periods (rows: 12)");
    println!("| family | strokes | by hand | accepted | accepted after 2 periods | shown | wrong | median ms | slowest ms (native) |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let only = std::env::var("FAMILY").ok();
    for f in family_list().into_iter().filter(|f| only.as_deref().is_none_or(|o| o == f.name)) {
        let (x, y) = if f.lattice.b.is_some() { (8.0, 6.0) } else { (12.0, 1.0) };
        let (ex, canvas) = f.canvas(x, y, jitter, seed);
        let r = replay(&ex.strokes, &ex.classes, canvas, 0.3 * f.lattice.spacing());
        let skip = 2 * f.lattice.motif.len();
        println!(
            "| {} | {} | {} | {} | {:.1}% | {} | {} ({:.1}%) | {:.2} | {:.2} |",
            f.name,
            r.strokes,
            r.by_hand,
            r.accepted,
            100.0 * r.accepted_after(skip),
            r.shown,
            r.wrong,
            100.0 * r.wrong_share(),
            r.median_ms,
            r.slowest_ms
        );
    }
    // Motifs of several strokes drawn by hand (vector::handdrawn), 8 x 6 copies.
    println!("\n| motif | lattice | strokes | by hand | accepted | accepted after 2 copies | shown | wrong | median ms | slowest ms (native) |");
    println!("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let spacing = 70.0;
    let only_motif = std::env::var("MOTIF").ok();
    for motif in patternsynth::vector::handdrawn::motifs()
        .into_iter()
        .filter(|m| only_motif.as_deref().is_none_or(|o| o == m.name))
    {
        let only_lattice = std::env::var("LATTICE").ok();
        for (lattice, a, b) in patternsynth::vector::handdrawn::lattices()
            .into_iter()
            .filter(|l| only_lattice.as_deref().is_none_or(|o| o == l.0))
        {
            let (ex, canvas) =
                patternsynth::vector::handdrawn::draw_over(&motif, (a, b), (8.0, 6.0), spacing, jitter, seed);
            let r = replay(&ex.strokes, &ex.classes, canvas, 0.3 * spacing);
            println!(
                "| {} | {lattice} | {} | {} | {} | {:.1}% | {} | {} ({:.1}%) | {:.2} | {:.2} |",
                motif.name,
                r.strokes,
                r.by_hand,
                r.accepted,
                100.0 * r.accepted_after(2 * motif.parts.len()),
                r.shown,
                r.wrong,
                100.0 * r.wrong_share(),
                r.median_ms,
                r.slowest_ms
            );
        }
    }
    // Repetitions that are not lattices (issue 27): rings, a spiral, leaves on an arc,
    // turning hatching; a ghost matches within 0.3 of the step.
    println!("\n| sequence | strokes | by hand | accepted | accepted after 3 copies | shown | wrong | median ms | slowest ms (native) |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let only_sequence = std::env::var("SEQUENCE").ok();
    // (HAND_TURN: degrees a hand turns each copy off at random, as a person does; 0,
    // the steady hand, by default.)
    let turn = std::env::var("HAND_TURN").ok().and_then(|t| t.parse::<f64>().ok()).unwrap_or(0.0).to_radians();
    let hand = patternsynth::vector::sequences::HandTurn(turn);
    for q in patternsynth::vector::sequences::drawn_by(jitter, hand, seed)
        .into_iter()
        .chain(patternsynth::vector::sequences::composite(jitter, hand, seed))
        .chain(patternsynth::vector::sequences::along_drawn(jitter, hand, seed))
        .filter(|q| only_sequence.as_deref().is_none_or(|o| q.name.starts_with(o)))
    {
        if let Ok(dir) = std::env::var("DUMP") {
            // The drawing to look at: each stroke a polyline.
            let lines: String = q
                .strokes
                .iter()
                .map(|s| {
                    let pts: Vec<String> = s.points.iter().map(|p| format!("{:.1},{:.1}", p[0], p[1])).collect();
                    format!("<polyline points='{}' fill='none' stroke='black' stroke-width='2'/>", pts.join(" "))
                })
                .collect();
            let svg = format!("<svg xmlns='http://www.w3.org/2000/svg' width='600' height='600'>{lines}</svg>");
            std::fs::write(format!("{dir}/{}.svg", q.name.replace(' ', "-")), svg).unwrap();
        }
        let r = q.replay(&q.strokes);
        println!(
            "| {} | {} | {} | {} | {:.1}% | {} | {} ({:.1}%) | {:.2} | {:.2} |",
            q.name,
            r.strokes,
            r.by_hand,
            r.accepted,
            100.0 * q.accepted_after_three(&r),
            r.shown,
            r.wrong,
            100.0 * r.wrong_share(),
            r.median_ms,
            r.slowest_ms
        );
    }
    // Input with no repetition: every prefix of the drawing, nothing may be proposed.
    let quiet = |name: &str, strokes: &[patternsynth::vector::Stroke]| {
        let mut shown = 0;
        for n in 1..=strokes.len() {
            shown += suggest_strokes(&strokes[..n], &SuggestOptions::default()).unwrap().strokes.len();
        }
        println!("{name}: {} strokes drawn one by one, {shown} proposals shown", strokes.len());
    };
    for seed in 1..=3 {
        quiet(&format!("irregular dashes (seed {seed})"), &irregular_dashes(60, 300.0, seed));
        quiet(&format!("freehand sketch (seed {seed})"), &freehand_sketch(40, 300.0, seed));
    }
}
