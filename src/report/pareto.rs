//! The Pareto set of each scene and the cheapest point within a budget.

use super::figures::PointFigures;

/// The points of a result set on the Pareto front of their scene: no other point of the scene is as cheap, as
/// accurate (mean colour error) and as fast (clocks a pixel), and better in one. (A k-clock variant's lower cost
/// buys a k-th of the rate, so it cannot push a one-clock point off the front.)
pub fn pareto(rs: &[PointFigures]) -> Vec<bool> {
    rs.iter()
        .map(|a| {
            !rs.iter().any(|b| {
                b.scene == a.scene
                    && b.cost() <= a.cost()
                    && b.colour.0 <= a.colour.0
                    && b.clocks() <= a.clocks()
                    && (b.cost() < a.cost() || b.colour.0 < a.colour.0 || b.clocks() < a.clocks())
            })
        })
        .collect()
}

/// The cheapest point of each scene whose mean colour error is within the budget, at one pixel a clock (the
/// project's rate; a k-clock variant is priced beside it, not chosen for it).
pub fn cheapest(rs: &[PointFigures], budget: f64) -> Vec<(&str, Option<&PointFigures>)> {
    let mut scenes: Vec<&str> = vec![];
    for r in rs {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
    }
    scenes
        .into_iter()
        .map(|s| {
            let within = |r: &&PointFigures| r.scene == s && r.colour.0 <= budget && r.clocks() == 1;
            (s, rs.iter().filter(within).min_by_key(|r| (r.cost(), r.id.clone())))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    fn r(id: &str, scene: &str, lut4: u64, dsp: u64, err: f64) -> PointFigures {
        PointFigures { id: id.into(), scene: scene.into(), lut4, dsp, colour: (err, err * 10.0), ..Default::default() }
    }

    #[test]
    fn the_pareto_set_and_the_cheapest_within_a_budget_are_per_scene() {
        let rs = vec![
            r("a", "s", 1000, 0, 1.0),
            r("b", "s", 500, 2, 2.0),
            r("c", "s", 2000, 0, 0.5),
            r("d", "s", 3000, 0, 0.9),
            r("e", "t", 9000, 0, 9.0),
            PointFigures { interval: 2, ..r("f", "s", 600, 0, 1.0) },
        ];
        // b costs 500 + 530 = 1030 > a's 1000 with more error: off; d is beaten by c; f is a's error for less, at
        // two clocks a pixel: neither pushes the other off
        assert_eq!(pareto(&rs), [true, false, true, false, true, true]);
        let c = cheapest(&rs, 1.0);
        assert_eq!(
            c.iter().map(|(s, r)| (*s, r.map(|r| r.id.as_str()))).collect::<Vec<_>>(),
            [("s", Some("a")), ("t", None)],
            "the cheapest at one pixel a clock, not f"
        );
        assert_eq!(cheapest(&rs, 0.6)[0].1.map(|r| r.id.as_str()), Some("c"));
    }
}
