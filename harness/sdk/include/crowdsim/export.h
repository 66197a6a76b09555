// The SDK's export macro: libcrowdsim_sdk.so hides every symbol not marked with it.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define CROWDSIM_SDK_API __attribute__((visibility("default")))
#else
#define CROWDSIM_SDK_API
#endif
