mod support;
#[test]
fn probe() {
    for name in [
        "08_openplc_samples_OpenSWat",
        "14_matiec_LD_TEST_tc6v1",
        "15_matiec_STD_TEST_tc6v1_fbd",
        "09_openplc_samples_vc999v3",
        "01_beremiz_first_steps",
        "02_beremiz_svghmi_traffic_light",
    ] {
        let text = std::fs::read_to_string(format!("/tmp/ladil/{name}.il")).unwrap();
        let mut map = diagnostics::SourceMap::new();
        let mut diags = diagnostics::Diagnostics::new();
        let dir = tempfile::tempdir().unwrap();
        let r = c_backend::build_il(
            &mut map,
            &[(format!("{name}.il"), text)],
            &Default::default(),
            &Default::default(),
            dir.path(),
            &support::strict(),
            &mut diags,
        );
        println!("== {name}: {:?}", r.as_ref().map(|x| x.is_some()));
        if let Err(e) = &r {
            println!("{}", &e.to_string()[..e.to_string().len().min(3000)]);
        }
        for d in diags
            .iter()
            .filter(|d| d.severity == diagnostics::Severity::Error)
            .take(8)
        {
            println!("{}", diagnostics::render_short(&map, d));
        }
    }
}
