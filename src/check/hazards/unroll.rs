//! Control flow of witness runs ([`super::witness`]): a loop's iterations are followed one
//! by one while each is surely reached (the inputs are points, so its exit tests are
//! decided), and a `switch` on a known selector takes its case only. What a witness run
//! cannot follow exactly, it over-approximates as the interval analysis does, marked unsure.

use naga::{Block, Expression, Handle, SwitchCase, SwitchValue};

use super::walk::{Analyzer, Call, Exits, State, UNROLL_LIMIT};

impl Analyzer<'_> {
    /// A loop in a witness run: iterations one by one while the head is surely reached,
    /// then the rest (if any) to a fixpoint.
    pub(super) fn unroll(
        &mut self,
        c: &mut Call<'_>,
        body: &Block,
        continuing: &Block,
        break_if: Option<Handle<Expression>>,
        entry: State,
    ) -> State {
        let (sure, before) = (entry.sure, self.exits);
        let mut head = entry;
        let mut out = State::dead();
        for round in 0..=UNROLL_LIMIT {
            if !head.live {
                break;
            }
            if !head.sure || round == UNROLL_LIMIT {
                // Past the limit on a sure path the loop really runs that long at these
                // inputs: a counter the fixpoint finds unbounded surely overflows.
                let runaway = head.sure;
                if runaway {
                    self.runaway.push(continuing as *const Block as usize);
                }
                let rest = self.run_loop(c, body, continuing, break_if, head);
                if runaway {
                    self.runaway.pop();
                }
                out = out.join(&rest, &mut self.fresh);
                break;
            }
            let (next, exit) = self.loop_round(c, body, continuing, break_if, head);
            out = out.join(&exit, &mut self.fresh);
            head = next;
        }
        // `break` and `continue` stay inside the loop; code after a loop that ends runs as
        // surely as the loop, unless a `return` or `discard` in it may have left first.
        let leaves = self.exits.leaves;
        self.exits = before;
        self.exits.leaves = leaves;
        if out.live {
            out.sure = sure && leaves == before.leaves;
        }
        out
    }

    /// A `switch` in a witness run: a selector known to one value takes the case it selects
    /// (falling through as GLSL does); otherwise every case, unsure.
    pub(super) fn witness_switch(
        &mut self,
        c: &mut Call<'_>,
        selector: Handle<Expression>,
        cases: &[SwitchCase],
        state: State,
        exits: &mut Exits,
    ) -> State {
        let (sure, before) = (state.sure, self.exits);
        let value = self.value(c, &state, selector).num().map(|n| n.iv()).filter(|iv| iv.is_point()).map(|iv| iv.lo);
        let selects = |v: &SwitchValue| match (*v, value) {
            (SwitchValue::I32(i), Some(x)) => f64::from(i) == x,
            (SwitchValue::U32(u), Some(x)) => f64::from(u) == x,
            _ => false,
        };
        let start = match value {
            Some(_) => cases.iter().position(|k| selects(&k.value)).or_else(|| cases.iter().position(|k| k.value == SwitchValue::Default)),
            None => None,
        };
        let mut inner = Exits::default();
        let mut out = State::dead();
        match start {
            Some(first) => {
                let mut entry = state;
                for case in &cases[first..] {
                    let end = self.block(c, &case.body, entry, &mut inner);
                    if !case.fall_through {
                        out = end;
                        break;
                    }
                    entry = end;
                }
            }
            None if value.is_some() => out = state,
            None => out = self.every_case(c, cases, state.unsure(), &mut inner),
        }
        let mut out = self.close_switch(out, inner, exits);
        // `break` leaves the switch only: the code after it runs as surely as the switch,
        // unless a case may have returned, discarded or continued the loop.
        let taken = self.exits;
        self.exits.breaks = before.breaks;
        if out.live {
            out.sure = sure && taken.leaves == before.leaves && taken.continues == before.continues;
        }
        out
    }
}
