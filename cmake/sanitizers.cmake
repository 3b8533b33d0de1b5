# meshedit_set_sanitizers(target): ASan + UBSan when MESHEDIT_SANITIZE is on. Applied to every
# project target (libraries and tests alike) so their runtimes agree.
function(meshedit_set_sanitizers target)
    if(MESHEDIT_FUZZ)
        # Coverage for libFuzzer everywhere; the fuzz executables add -fsanitize=fuzzer.
        target_compile_options(${target} PRIVATE
            -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
            -fno-omit-frame-pointer)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    elseif(MESHEDIT_SANITIZE)
        target_compile_options(${target} PRIVATE
            -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
endfunction()

# meshedit_configure_target(target): the per-target settings every project target shares.
function(meshedit_configure_target target)
    target_compile_features(${target} PUBLIC cxx_std_20)
    meshedit_set_warnings(${target})
    meshedit_set_sanitizers(${target})
endfunction()
