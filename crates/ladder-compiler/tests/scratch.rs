mod common;
#[test]
fn scratch() {
    for f in [
        "01_beremiz_first_steps.xml",
        "02_beremiz_svghmi_traffic_light.xml",
        "04_beremiz_ethercat_wago_higen_MC.xml",
        "05_beremiz_ethercat_wago_sanyo_MC.xml",
        "08_openplc_samples_OpenSWat.xml",
        "09_openplc_samples_vc999v3.xml",
        "10_openplc_samples_esp8266celsius.xml",
        "11_openplc_samples_PT_Motor_PID_Wave_fbd.xml",
        "14_matiec_LD_TEST_tc6v1.xml",
        "15_matiec_STD_TEST_tc6v1_fbd.xml",
        "24_feecat_S7RTT_codesys_st_motion.xml",
    ] {
        let (u, d) = common::compile(f, &common::corpus(f));
        println!("=== {f}: {} items\n{d}", u.items.len());
    }
}
