//! The jobs list: a page planned from its jobs' sizes (so the answer's
//! memory is reserved for what it holds before they are read), then its
//! jobs read; each filter's queries written for its index.

use super::backend::on_pool;
use super::{JobRow, Row, Store, StoreError, row_columns};

/// Which jobs a page of the list holds, before they are read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    /// The seqs of its first (newest) and last job; None for an empty page.
    pub seqs: Option<(i64, i64)>,
    /// Bytes of their requests and results together.
    pub bytes: usize,
    /// Whether the page stopped at its size in bytes (more jobs follow).
    pub cut: bool,
}

/// Which jobs a list holds: of one kind, of one label (None: any).
#[derive(Clone, Copy, Debug, Default)]
pub struct Filter<'a> {
    pub kind: Option<&'a str>,
    pub label: Option<&'a str>,
}

impl<'a> Filter<'a> {
    /// `q` with the filter's values bound after its two seqs, as [`list_sql`] numbers them.
    fn bind<DB: sqlx::Database, O>(
        &self,
        q: sqlx::query::QueryAs<'a, DB, O, <DB as sqlx::Database>::Arguments>,
    ) -> sqlx::query::QueryAs<'a, DB, O, <DB as sqlx::Database>::Arguments>
    where
        &'a str: sqlx::Encode<'a, DB> + sqlx::Type<DB>,
    {
        self.label.into_iter().fold(self.kind.into_iter().fold(q, |q, k| q.bind(k)), |q, l| q.bind(l))
    }
}

impl Store {
    /// Which jobs a page of the list holds: up to `limit`, newest first, of
    /// `filter`, older than `before` (a seq), stopping before their requests
    /// and results together exceed `max_bytes` (one job at least). Only
    /// their sizes are read, so the answer's memory is reserved for what it
    /// holds before the jobs are loaded ([`Store::list_rows`]).
    pub async fn list_plan(
        &self,
        filter: &Filter<'_>,
        before: Option<i64>,
        limit: i64,
        max_bytes: usize,
    ) -> Result<Plan, StoreError> {
        let sql = list_sql(filter).0;
        let before = before.unwrap_or(i64::MAX);
        let sizes: Vec<(i64, i64)> = on_pool!(&self.db, pool => {
            let q = sqlx::query_as(sql).bind(before).bind(limit);
            filter.bind(q).fetch_all(pool).await?
        });
        let mut plan = Plan { seqs: None, bytes: 0, cut: false };
        for (i, &(seq, bytes)) in sizes.iter().enumerate() {
            let bytes = usize::try_from(bytes).unwrap_or(0);
            if i > 0 && plan.bytes + bytes > max_bytes {
                plan.cut = true;
                break;
            }
            plan.bytes += bytes;
            plan.seqs = Some((plan.seqs.map_or(seq, |(first, _)| first), seq));
        }
        Ok(plan)
    }

    /// The jobs of a [`Store::list_plan`] (those deleted since are missing).
    pub async fn list_rows(&self, filter: &Filter<'_>, plan: &Plan) -> Result<Vec<JobRow>, StoreError> {
        let Some((first, last)) = plan.seqs else { return Ok(Vec::new()) };
        let sql = list_sql(filter).1;
        let rows: Vec<Row> = on_pool!(&self.db, pool => {
            let q = sqlx::query_as(sql).bind(first).bind(last);
            filter.bind(q).fetch_all(pool).await?
        });
        rows.into_iter().map(JobRow::try_from).collect()
    }
}

/// The queries of a page of the list for `filter` (each on its index: the
/// label's, the kind's, or the table's order; one query for every filter,
/// `(? IS NULL OR kind = ?)`, was planned on the table's order and read it
/// all): the sizes ($1 before, $2 limit) and the rows ($1 first, $2 last),
/// then $3 the kind or label, $4 the label with a kind.
pub fn list_sql(filter: &Filter<'_>) -> (&'static str, &'static str) {
    macro_rules! queries {
        ($where:literal) => {
            (
                concat!("SELECT seq, bytes FROM jobs WHERE ", $where, "seq < $1 ORDER BY seq DESC LIMIT $2"),
                concat!(
                    "SELECT ",
                    row_columns!(),
                    " FROM jobs WHERE ",
                    $where,
                    "seq <= $1 AND seq >= $2 ORDER BY seq DESC"
                ),
            )
        };
    }
    match (filter.kind, filter.label) {
        (None, None) => queries!(""),
        (Some(_), None) => queries!("kind = $3 AND "),
        (None, Some(_)) => queries!("label = $3 AND "),
        (Some(_), Some(_)) => queries!("label = $4 AND kind = $3 AND "),
    }
}
